// verse_node_pool.cpp — see verse_node_pool.h.
#include "verse_node_pool.h"

namespace vgc {
namespace {

// A fresh node holds two empty layers; a pool node the host sends more
// than this for is spoilt anyway, and the bound keeps a hostile host from
// making vgc allocate a full mirror's worth for each node of the pool.
constexpr std::size_t kPoolMirrorCells = 4096;

}  // namespace

void VerseNodePool::add(std::uint32_t node_id) {
  Entry e{VerseNodeMirror(kPoolMirrorCells), false, false, false, false, {}};
  nodes_[node_id] = std::move(e);
}

VerseNodeMirror* VerseNodePool::mirror(std::uint32_t node_id) {
  const auto it = nodes_.find(node_id);
  return it == nodes_.end() ? nullptr : &it->second.mirror;
}

bool VerseNodePool::settled(std::uint32_t node_id) const {
  const auto it = nodes_.find(node_id);
  return it != nodes_.end() && it->second.settled;
}

void VerseNodePool::on_index_create(std::uint32_t node_id) {
  if (const auto it = nodes_.find(node_id); it != nodes_.end()) it->second.announced = true;
}

void VerseNodePool::on_index_destroy(std::uint32_t node_id) {
  // Before its node_create was read, a destroy is an earlier node's of the
  // same id (verse_node_pool.h).
  if (const auto it = nodes_.find(node_id); it != nodes_.end() && it->second.announced)
    it->second.destroyed = true;
}

void VerseNodePool::spoil(std::uint32_t node_id) {
  if (const auto it = nodes_.find(node_id); it != nodes_.end()) it->second.spoilt = true;
}

void VerseNodePool::settle_all() {
  for (auto& [id, e] : nodes_) {
    if (e.settled) continue;
    e.settled = true;
    e.fresh = e.mirror.snapshot();
  }
}

std::optional<VerseNodePool::Taken> VerseNodePool::take(std::vector<std::uint32_t>* spoilt) {
  while (!nodes_.empty()) {
    auto it = nodes_.begin();
    Entry& e = it->second;
    const bool fresh =
        e.settled && e.announced && !e.destroyed && !e.spoilt && e.mirror.snapshot() == e.fresh;
    if (!fresh) {
      if (!e.destroyed) spoilt->push_back(it->first);
      nodes_.erase(it);
      continue;
    }
    Taken t{it->first, std::move(e.mirror)};
    nodes_.erase(it);
    return t;
  }
  return std::nullopt;
}

std::vector<std::uint32_t> VerseNodePool::clear() {
  std::vector<std::uint32_t> ids;
  for (const auto& [id, e] : nodes_)
    if (!e.destroyed) ids.push_back(id);
  nodes_.clear();
  return ids;
}

}  // namespace vgc
