// Network: construction, copying, lookup, equality and the low-level
// mutators that keep the derived curve -> node / patch maps in sync.
#include "sketchlab/network.hpp"

#include "spatial_index.hpp"

namespace sketchlab {

Network::Network() : index_(std::make_unique<SpatialIndex>()) {}

Network::~Network() = default;

Network::Network(const Network& other)
    : curves_(other.curves_),
      nodes_(other.nodes_),
      patches_(other.patches_),
      counters_(other.counters_),
      nodes_on_curve_(other.nodes_on_curve_),
      patches_on_curve_(other.patches_on_curve_),
      index_(other.index_ ? std::make_unique<SpatialIndex>(*other.index_) : std::make_unique<SpatialIndex>()) {}

Network& Network::operator=(const Network& other) {
  if (this != &other) {
    Network copy(other);
    *this = std::move(copy);
  }
  return *this;
}

// A moved-from network is left empty (and re-creates its index on the next
// apply), so it stays usable.
Network::Network(Network&& other) noexcept
    : curves_(std::move(other.curves_)),
      nodes_(std::move(other.nodes_)),
      patches_(std::move(other.patches_)),
      counters_(other.counters_),
      nodes_on_curve_(std::move(other.nodes_on_curve_)),
      patches_on_curve_(std::move(other.patches_on_curve_)),
      index_(std::move(other.index_)) {
  other.curves_.clear();
  other.nodes_.clear();
  other.patches_.clear();
  other.nodes_on_curve_.clear();
  other.patches_on_curve_.clear();
  other.counters_ = IdCounters{};
}

Network& Network::operator=(Network&& other) noexcept {
  if (this != &other) {
    curves_ = std::move(other.curves_);
    nodes_ = std::move(other.nodes_);
    patches_ = std::move(other.patches_);
    counters_ = other.counters_;
    nodes_on_curve_ = std::move(other.nodes_on_curve_);
    patches_on_curve_ = std::move(other.patches_on_curve_);
    index_ = std::move(other.index_);
    other.curves_.clear();
    other.nodes_.clear();
    other.patches_.clear();
    other.nodes_on_curve_.clear();
    other.patches_on_curve_.clear();
    other.counters_ = IdCounters{};
  }
  return *this;
}

const NetworkCurve* Network::find_curve(CurveId id) const {
  auto it = curves_.find(id);
  return it == curves_.end() ? nullptr : &it->second;
}

const Node* Network::find_node(NodeId id) const {
  auto it = nodes_.find(id);
  return it == nodes_.end() ? nullptr : &it->second;
}

bool Network::operator==(const Network& other) const {
  return counters_ == other.counters_ && curves_ == other.curves_ && nodes_ == other.nodes_ &&
         patches_ == other.patches_;
}

std::vector<PatchId> Network::patches_on(CurveId curve) const {
  auto it = patches_on_curve_.find(curve);
  if (it == patches_on_curve_.end()) return {};
  return {it->second.begin(), it->second.end()};
}

void Network::put_curve(const NetworkCurve& curve) { curves_[curve.id] = curve; }

void Network::erase_curve(CurveId id) { curves_.erase(id); }

namespace {

template <class Map, class Id>
void unlink(Map& map, CurveId curve, Id id) {
  auto it = map.find(curve);
  if (it == map.end()) return;
  it->second.erase(id);
  if (it->second.empty()) map.erase(it);
}

}  // namespace

void Network::put_node(const Node& node) {
  erase_node(node.id);
  for (const NodeIncidence& inc : node.incidences) nodes_on_curve_[inc.curve].insert(node.id);
  nodes_.emplace(node.id, node);
}

void Network::erase_node(NodeId id) {
  auto it = nodes_.find(id);
  if (it == nodes_.end()) return;
  for (const NodeIncidence& inc : it->second.incidences) unlink(nodes_on_curve_, inc.curve, id);
  nodes_.erase(it);
}

void Network::put_patch(const Patch& patch) {
  erase_patch(patch.id);
  for (const OrientedSegment& s : patch.boundary) patches_on_curve_[s.curve].insert(patch.id);
  patches_.emplace(patch.id, patch);
}

void Network::erase_patch(PatchId id) {
  auto it = patches_.find(id);
  if (it == patches_.end()) return;
  for (const OrientedSegment& s : it->second.boundary) unlink(patches_on_curve_, s.curve, id);
  patches_.erase(it);
}

void Network::index_curve(CurveId id, const std::optional<NetworkCurve>& old_curve) {
  const NetworkCurve* now = find_curve(id);
  if (old_curve && now && *old_curve == *now) return;
  if (old_curve) index_->erase_curve(id);
  if (now) index_->insert_curve(*now);
}

void Network::index_node(NodeId id, const std::optional<Node>& old_node) {
  const Node* now = find_node(id);
  if (old_node && now && old_node->position == now->position) return;
  if (old_node) index_->erase_node(id);
  if (now) index_->insert_node(*now);
}

}  // namespace sketchlab
