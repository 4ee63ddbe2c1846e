// verse_node_pool.h — fresh geometry nodes of a Verse host, made ahead in
// batches, for the verse: route's reset() (verse_implementation.h).
//
// Spec: docs/adapters.md section 7 ("?reset (a fresh node, before every
// test case)"); docs/verse_wire.md section 3 (node_create, node_destroy,
// the index and how r6 reuses ids) and "Where the time of a wire run goes".
//
// Rationale: a certification resets the node before every case, some ten
// thousand times a run against r6, and making one node costs three round
// trips through the host (the node_create, the observer's subscription to
// the node, then to its base layers), each a few milliseconds on a loaded
// machine because r6 polls its socket in a loop that competes for the CPU.
// Made in batches, the same three round trips give many nodes, so a reset
// costs a fraction of one. A node made ahead is as fresh as one made at the
// reset only while nothing touched it; what can touch it is r6 running
// bytes it misread (a desynchronised packet, docs/verse_wire.md section 1)
// as commands for some node. So the observer stays subscribed to every node
// of the pool and follows the node index, and a node is handed out only if
// it is still alive and its state is still, to the byte, the state it was
// first seen in; any other is given back to be destroyed.
//
// Index events come with r6's reuse of ids: a node_destroy the observer
// reads for an id may be the destroy of an earlier node that had that id
// (the route's own destroy at a reset, read after the new node was made).
// A pool node therefore counts as destroyed only by a node_destroy read
// after the observer read its node_create: r6 sends a subscriber both in
// the order it ran them (or only the last, when both wait in its out-queue
// under one address, section 3).
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "verse_node_mirror.h"

namespace vgc {

class VerseNodePool {
 public:
  // A node the driver's node_create made (not yet subscribed by the observer).
  void add(std::uint32_t node_id);
  bool holds(std::uint32_t node_id) const { return nodes_.count(node_id) > 0; }
  // Its mirror, where the observer's commands for it go; null when not held.
  VerseNodeMirror* mirror(std::uint32_t node_id);
  // Whether its subscriptions settled (new layers of a settled node are not
  // subscribed to: the node is spoilt anyway).
  bool settled(std::uint32_t node_id) const;

  // The observer read node_create / node_destroy of geometry node `node_id`.
  void on_index_create(std::uint32_t node_id);
  void on_index_destroy(std::uint32_t node_id);

  // The host sent more for it than a fresh node holds (its mirror refused
  // it): it will not be handed out.
  void spoil(std::uint32_t node_id);

  // The subscriptions of every node added so far settled: each one's state
  // now is its fresh state.
  void settle_all();

  struct Taken {
    std::uint32_t node_id = 0;
    VerseNodeMirror mirror;
  };
  // A settled node, alive, in its fresh state, out of the pool (lowest id
  // first); nullopt when none is left. Nodes found spoilt on the way are
  // dropped from the pool and their ids appended to *spoilt (to destroy).
  std::optional<Taken> take(std::vector<std::uint32_t>* spoilt);

  // The id of every node still alive, and the pool emptied (a new session
  // starts over).
  std::vector<std::uint32_t> clear();
  bool empty() const { return nodes_.empty(); }
  std::size_t size() const { return nodes_.size(); }

 private:
  struct Entry {
    VerseNodeMirror mirror;
    bool announced = false;  // the observer read its node_create
    bool destroyed = false;  // ... and then a node_destroy
    bool settled = false;
    bool spoilt = false;
    std::string fresh;       // mirror.snapshot() when it settled
  };
  std::map<std::uint32_t, Entry> nodes_;
};

}  // namespace vgc
