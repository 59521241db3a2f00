#include "timed_soapfilm.hpp"

#include <chrono>
#include <ctime>
#include <utility>

namespace sketchlab::soapfilm {

double thread_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

namespace {

template <class F>
SurfaceUpdate timed(SurfacerCost& cost, F&& f) {
  const auto w0 = std::chrono::steady_clock::now();
  const double c0 = thread_cpu_ms();
  SurfaceUpdate u = f();
  cost.cpu_ms += thread_cpu_ms() - c0;
  cost.wall_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - w0).count();
  return u;
}

}  // namespace

SurfaceUpdate TimedSoapfilm::update(const Sketch& sketch, const Edit& last) {
  return timed(cost_, [&] { return soapfilm_update(sketch, last, params_, &cost_.meshed); });
}

SurfaceUpdate TimedSoapfilm::command(const Sketch& sketch, const SurfaceCommand& command) {
  return timed(cost_, [&] { return soapfilm_command(sketch, command, params_); });
}

SurfacerCost TimedSoapfilm::take() { return std::exchange(cost_, SurfacerCost{}); }

}  // namespace sketchlab::soapfilm
