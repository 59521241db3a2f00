#include "spatial_index.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "sketchlab/geometry/bounding_box.hpp"

namespace sketchlab {

namespace {

// Cell coordinates are clamped so that huge coordinates or tiny cells cannot
// overflow; clamped items pile up in border cells, which stays correct because
// queries clamp the same way.
constexpr double kCellCoordLimit = 1 << 30;
// A cubic segment longer than a cell is cut into at most this many chunks.
constexpr int kMaxChunksPerSegment = 1024;
// A chunk box spanning more cells than this goes to the oversized list. A
// chunk about one cell long spans at most 2 cells per axis, 3 with its
// slack on a cell boundary: 27 cells.
constexpr double kMaxCellsPerChunk = 64;
// Extents fed to the cell-size statistic are clamped to this range (metres)
// so that a degenerate (point-like) or absurd segment cannot drag it to 0 or
// infinity.
constexpr double kMinExtent = 1e-6;
constexpr double kMaxExtent = 1e3;

// Chunk boxes are inflated by this much so that points evaluated on the curve
// (with rounding) never fall outside the box of their own piece.
double box_slack(const Box3& box) {
  const double scale = std::max(box.min().cwiseAbs().maxCoeff(), box.max().cwiseAbs().maxCoeff());
  return 1e-9 + 1e-12 * scale;
}

double max_extent(const Box3& box) { return (box.max() - box.min()).maxCoeff(); }

// Does the segment [a, b] meet the closed box? (slab test)
bool segment_meets_box(const Vec3& a, const Vec3& b, const Vec3& lo, const Vec3& hi) {
  double t0 = 0.0, t1 = 1.0;
  const Vec3 d = b - a;
  for (int i = 0; i < 3; ++i) {
    if (d[i] == 0.0) {
      if (a[i] < lo[i] || a[i] > hi[i]) return false;
      continue;
    }
    double ta = (lo[i] - a[i]) / d[i];
    double tb = (hi[i] - a[i]) / d[i];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

template <class Map, class Key, class Pred>
void erase_from_cell(Map& grid, const Key& key, Pred&& pred) {
  auto it = grid.find(key);
  if (it == grid.end()) return;
  auto& items = it->second;
  items.erase(std::remove_if(items.begin(), items.end(), pred), items.end());
  if (items.empty()) grid.erase(it);
}

}  // namespace

std::size_t SpatialIndex::CellHash::operator()(const CellKey& k) const noexcept {
  std::uint64_t h = static_cast<std::uint64_t>(static_cast<std::uint32_t>(k.x)) * 0x9E3779B97F4A7C15ull;
  h ^= static_cast<std::uint64_t>(static_cast<std::uint32_t>(k.y)) * 0xC2B2AE3D27D4EB4Full;
  h ^= static_cast<std::uint64_t>(static_cast<std::uint32_t>(k.z)) * 0x165667B19E3779F9ull;
  h ^= h >> 29;
  return static_cast<std::size_t>(h);
}

double SpatialIndex::CellRange::count() const {
  return (double(hi.x) - lo.x + 1) * (double(hi.y) - lo.y + 1) * (double(hi.z) - lo.z + 1);
}

bool SpatialIndex::CellRange::contains(const CellKey& k) const {
  return k.x >= lo.x && k.x <= hi.x && k.y >= lo.y && k.y <= hi.y && k.z >= lo.z && k.z <= hi.z;
}

SpatialIndex::CellKey SpatialIndex::cell_of(const Vec3& p) const {
  auto coord = [&](double v) {
    const double c = std::clamp(std::floor(v / cell_), -kCellCoordLimit, kCellCoordLimit);
    return static_cast<std::int32_t>(c);
  };
  return {coord(p.x()), coord(p.y()), coord(p.z())};
}

SpatialIndex::CellRange SpatialIndex::range_of(const Box3& box) const {
  return {cell_of(box.min()), cell_of(box.max())};
}

template <class Grid, class F>
void SpatialIndex::for_cells(const Grid& grid, const CellRange& range, F&& f) const {
  if (grid.empty()) return;
  if (range.count() <= static_cast<double>(grid.size())) {
    for (std::int32_t x = range.lo.x; x <= range.hi.x; ++x)
      for (std::int32_t y = range.lo.y; y <= range.hi.y; ++y)
        for (std::int32_t z = range.lo.z; z <= range.hi.z; ++z) {
          auto it = grid.find(CellKey{x, y, z});
          if (it != grid.end()) f(it->second);
        }
  } else {
    // A query much larger than the data: walking the occupied cells is
    // cheaper than probing every cell of the range.
    for (const auto& [key, items] : grid)
      if (range.contains(key)) f(items);
  }
}

// The cell size is the geometric mean of the extents (largest box side) of
// the indexed cubic segments. Rationale: a cell about one segment wide keeps
// each chunk in O(1) cells and a query of radius r in O((r/h + 1)^3) cells,
// and fitted sketch curves have segments of a few centimetres, close to the
// papers' 2-5 cm thresholds. The extents are skewed (a few long scaffold
// lines among many short shape segments); like the median, the log-mean is
// dominated by the bulk, but unlike the median it updates in O(1) on every
// insert and erase. Long segments are cut into chunks of about a cell so
// that a long diagonal line does not fill a cube of cells with one box.
double SpatialIndex::target_cell_size() const {
  if (segment_count_ <= 0) return 0.0;
  return std::exp(log_extent_sum_ / static_cast<double>(segment_count_));
}

bool SpatialIndex::needs_rebuild() const {
  const double target = target_cell_size();
  if (target <= 0.0 || cell_ <= 0.0) return false;
  return target > 2.0 * cell_ || target < 0.5 * cell_;
}

void SpatialIndex::rebuild(const std::map<CurveId, NetworkCurve>& curves, const std::map<NodeId, Node>& nodes) {
  const double target = target_cell_size();
  *this = SpatialIndex();
  cell_ = target;
  for (const auto& [id, curve] : curves) insert_curve(curve);
  for (const auto& [id, node] : nodes) insert_node(node);
}

void SpatialIndex::insert_curve(const NetworkCurve& nc) {
  const Curve& curve = nc.curve;
  const int k_count = curve.segment_count();
  CurveRecord record;
  record.segment_count = k_count;
  std::vector<Box3> segment_boxes;
  segment_boxes.reserve(k_count);
  for (int k = 0; k < k_count; ++k) {
    segment_boxes.push_back(bounding_box(curve, k, k + 1));
    record.log_extent_sum += std::log(std::clamp(max_extent(segment_boxes.back()), kMinExtent, kMaxExtent));
  }
  log_extent_sum_ += record.log_extent_sum;
  segment_count_ += record.segment_count;
  if (cell_ <= 0.0) cell_ = k_count > 0 ? target_cell_size() : 0.05;

  for (int k = 0; k < k_count; ++k) {
    const double extent = max_extent(segment_boxes[k]);
    const int pieces = static_cast<int>(std::clamp(std::ceil(extent / cell_), 1.0, double(kMaxChunksPerSegment)));
    for (int i = 0; i < pieces; ++i) {
      Box3 box = pieces == 1 ? segment_boxes[k]
                             : bounding_box(curve, k + double(i) / pieces,
                                            i + 1 == pieces ? double(k + 1) : k + double(i + 1) / pieces);
      const double slack = box_slack(box);
      box.min().array() -= slack;
      box.max().array() += slack;
      const CellRange range = range_of(box);
      ++record.chunk_count;
      if (range.count() > kMaxCellsPerChunk) {
        oversized_.push_back(ChunkRef{nc.id, box});
        record.oversized = true;
        continue;
      }
      for (std::int32_t x = range.lo.x; x <= range.hi.x; ++x)
        for (std::int32_t y = range.lo.y; y <= range.hi.y; ++y)
          for (std::int32_t z = range.lo.z; z <= range.hi.z; ++z) {
            const CellKey key{x, y, z};
            curve_cells_[key].push_back(ChunkRef{nc.id, box});
            record.chunk_cells.push_back(key);
          }
    }
  }
  for (int i = 0; i < static_cast<int>(nc.keypoints.size()); ++i) {
    const Vec3& position = nc.keypoints[i].position;
    const CellKey key = cell_of(position);
    keypoint_cells_[key].push_back(KeypointRef{nc.id, i, position});
    record.keypoint_cells.push_back(key);
  }
  auto dedup = [](std::vector<CellKey>& keys) {
    auto less = [](const CellKey& a, const CellKey& b) {
      return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
    };
    std::sort(keys.begin(), keys.end(), less);
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  };
  dedup(record.chunk_cells);
  dedup(record.keypoint_cells);
  chunk_count_ += record.chunk_count;
  curves_[nc.id] = std::move(record);
}

void SpatialIndex::erase_curve(CurveId id) {
  auto it = curves_.find(id);
  if (it == curves_.end()) return;
  const CurveRecord& record = it->second;
  for (const CellKey& key : record.chunk_cells)
    erase_from_cell(curve_cells_, key, [&](const ChunkRef& c) { return c.curve == id; });
  for (const CellKey& key : record.keypoint_cells)
    erase_from_cell(keypoint_cells_, key, [&](const KeypointRef& k) { return k.curve == id; });
  if (record.oversized)
    oversized_.erase(std::remove_if(oversized_.begin(), oversized_.end(),
                                    [&](const ChunkRef& c) { return c.curve == id; }),
                     oversized_.end());
  log_extent_sum_ -= record.log_extent_sum;
  segment_count_ -= record.segment_count;
  chunk_count_ -= record.chunk_count;
  curves_.erase(it);
  if (curves_.empty()) {
    // Start afresh: no rounding drift in the statistic, and the next data
    // chooses its own cell size.
    log_extent_sum_ = 0.0;
    segment_count_ = 0;
    chunk_count_ = 0;
    if (nodes_.empty()) cell_ = 0.0;
  }
}

void SpatialIndex::insert_node(const Node& node) {
  if (cell_ <= 0.0) cell_ = 0.05;  // only reachable without curves; any size is correct
  const CellKey key = cell_of(node.position);
  node_cells_[key].push_back(NodeRef{node.id, node.position});
  nodes_[node.id] = key;
}

void SpatialIndex::erase_node(NodeId id) {
  auto it = nodes_.find(id);
  if (it == nodes_.end()) return;
  erase_from_cell(node_cells_, it->second, [&](const NodeRef& n) { return n.node == id; });
  nodes_.erase(it);
  if (nodes_.empty() && curves_.empty()) cell_ = 0.0;
}

std::vector<CurveId> SpatialIndex::curve_candidates(const Vec3& p, double r) const {
  std::vector<CurveId> out;
  if (cell_ <= 0.0) return out;
  const Box3 query(p.array() - r, p.array() + r);
  const double r2 = r * r;
  auto test = [&](const std::vector<ChunkRef>& items) {
    for (const ChunkRef& c : items)
      if (c.box.squaredExteriorDistance(p) <= r2) out.push_back(c.curve);
  };
  for_cells(curve_cells_, range_of(query), test);
  test(oversized_);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<CurveId> SpatialIndex::curve_candidates(const std::vector<Vec3>& polyline, double r) const {
  std::vector<CurveId> out;
  if (cell_ <= 0.0 || polyline.empty()) return out;
  const std::size_t pieces = polyline.size() == 1 ? 1 : polyline.size() - 1;
  for (std::size_t i = 0; i < pieces; ++i) {
    const Vec3& a = polyline[i];
    const Vec3& b = polyline.size() == 1 ? polyline[i] : polyline[i + 1];
    Box3 query(a.cwiseMin(b), a.cwiseMax(b));
    query.min().array() -= r;
    query.max().array() += r;
    auto test = [&](const std::vector<ChunkRef>& items) {
      for (const ChunkRef& c : items) {
        const Vec3 lo = c.box.min().array() - r;
        const Vec3 hi = c.box.max().array() + r;
        if (segment_meets_box(a, b, lo, hi)) out.push_back(c.curve);
      }
    };
    for_cells(curve_cells_, range_of(query), test);
    test(oversized_);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<KeypointHit> SpatialIndex::keypoints_near(const Vec3& p, double r) const {
  std::vector<KeypointHit> out;
  if (cell_ <= 0.0) return out;
  const Box3 query(p.array() - r, p.array() + r);
  for_cells(keypoint_cells_, range_of(query), [&](const std::vector<KeypointRef>& items) {
    for (const KeypointRef& k : items) {
      const double d = (k.position - p).norm();
      if (d <= r) out.push_back(KeypointHit{k.curve, k.keypoint, k.position, d});
    }
  });
  return out;
}

std::vector<NodeHit> SpatialIndex::nodes_near(const Vec3& p, double r) const {
  std::vector<NodeHit> out;
  if (cell_ <= 0.0) return out;
  const Box3 query(p.array() - r, p.array() + r);
  for_cells(node_cells_, range_of(query), [&](const std::vector<NodeRef>& items) {
    for (const NodeRef& n : items) {
      const double d = (n.position - p).norm();
      if (d <= r) out.push_back(NodeHit{n.node, d});
    }
  });
  return out;
}

}  // namespace sketchlab
