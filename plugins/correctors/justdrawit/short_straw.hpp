#pragma once
// ShortStraw corner finding (Wolin, Eoff & Hammond 2008), used by JustDrawIt
// to split a scratch stroke into candidate fold-over sections (§4.1).
#include <vector>

#include "point_list.hpp"

namespace sketchlab::justdrawit {

struct Corners {
  Points2 points;                  // the stroke resampled at spacing S = diagonal / 40
  std::vector<std::size_t> index;  // corner indices into `points`, first 0 and last n-1
};

// 2D stroke (pixels, >= 2 points) -> resampled points and corners.
// Straws over a window W = 3, threshold 0.95 x median straw, line test
// chord / path > 0.95 (the paper's constants).
Corners short_straw(const Points2& stroke);

}  // namespace sketchlab::justdrawit
