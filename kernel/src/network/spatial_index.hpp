#pragma once
// Private to the kernel: the spatial index behind Network's proximity
// queries. A uniform hash grid over
//  - curve chunks: each cubic segment of a curve, cut into pieces no larger
//    than about one cell, with its tight bounding box;
//  - keypoints and node positions (one cell each).
// A chunk that would still cover more than a few cells (a segment so long
// that even kMaxChunksPerSegment pieces are many cells wide: a tracking
// glitch kilometres away in a sketch of centimetre segments) is kept in a
// short list of oversized chunks that every query scans instead, so one
// absurd segment costs a list entry, not millions of cells.
// Queries return conservative candidate sets (every curve with a chunk box
// within r of the query); Network computes exact distances on them. Point
// items (keypoints, nodes) are answered exactly here.
#include <cstdint>
#include <map>
#include <unordered_map>
#include <vector>

#include "sketchlab/network.hpp"

namespace sketchlab {

class SpatialIndex {
 public:
  // Adds a curve's chunks and keypoints (the id must not be indexed yet).
  void insert_curve(const NetworkCurve& curve);
  // Removes everything indexed for the curve (no-op when absent).
  void erase_curve(CurveId id);
  void insert_node(const Node& node);
  void erase_node(NodeId id);

  // True when the cell size has drifted more than a factor 2 from what the
  // indexed curves suggest; rebuild() then re-indexes everything.
  bool needs_rebuild() const;
  void rebuild(const std::map<CurveId, NetworkCurve>& curves, const std::map<NodeId, Node>& nodes);

  // Ids (ascending, unique) of curves with a chunk box within distance r of p
  // (a superset of the curves within r of p).
  std::vector<CurveId> curve_candidates(const Vec3& p, double r) const;
  // Ids (ascending, unique) of curves with a chunk box whose r-expansion meets
  // some segment of the polyline (a superset of the curves within r of it).
  // The polyline has at least one point.
  std::vector<CurveId> curve_candidates(const std::vector<Vec3>& polyline, double r) const;
  // Exact: keypoints / nodes within r of p (inclusive), unsorted.
  std::vector<KeypointHit> keypoints_near(const Vec3& p, double r) const;
  std::vector<NodeHit> nodes_near(const Vec3& p, double r) const;

  double cell_size() const { return cell_; }
  std::size_t chunk_count() const { return chunk_count_; }
  std::size_t occupied_cells() const { return curve_cells_.size(); }
  std::size_t oversized_chunks() const { return oversized_.size(); }

 private:
  struct CellKey {
    std::int32_t x = 0, y = 0, z = 0;
    bool operator==(const CellKey&) const = default;
  };
  struct CellHash {
    std::size_t operator()(const CellKey& k) const noexcept;
  };
  struct CellRange {
    CellKey lo, hi;
    double count() const;
    bool contains(const CellKey& k) const;
  };
  struct ChunkRef {
    CurveId curve = 0;
    Box3 box;
  };
  struct KeypointRef {
    CurveId curve = 0;
    int keypoint = 0;
    Vec3 position;
  };
  struct NodeRef {
    NodeId node = 0;
    Vec3 position;
  };
  struct CurveRecord {
    std::vector<CellKey> chunk_cells;     // unique
    std::vector<CellKey> keypoint_cells;  // unique
    double log_extent_sum = 0.0;          // over its cubic segments
    int segment_count = 0;
    std::size_t chunk_count = 0;
    bool oversized = false;  // some chunk is in oversized_
  };

  CellKey cell_of(const Vec3& p) const;
  CellRange range_of(const Box3& box) const;
  // Calls f(cell key, items) for every occupied cell of `grid` in `range`,
  // walking whichever is smaller: the range or the occupied cells.
  template <class Grid, class F>
  void for_cells(const Grid& grid, const CellRange& range, F&& f) const;
  // The target cell size for the indexed data (0 when there is none).
  double target_cell_size() const;

  double cell_ = 0.0;  // 0 until the first curve fixes it
  std::unordered_map<CellKey, std::vector<ChunkRef>, CellHash> curve_cells_;
  std::vector<ChunkRef> oversized_;
  std::unordered_map<CellKey, std::vector<KeypointRef>, CellHash> keypoint_cells_;
  std::unordered_map<CellKey, std::vector<NodeRef>, CellHash> node_cells_;
  std::unordered_map<CurveId, CurveRecord> curves_;
  std::unordered_map<NodeId, CellKey> nodes_;
  double log_extent_sum_ = 0.0;
  long segment_count_ = 0;
  std::size_t chunk_count_ = 0;
};

}  // namespace sketchlab
