// packet_order.h — the order in which vgc's host applies the commands of
// one packet: layer commands, then base-layer vertex commands, then
// base-layer polygon commands, then everything else, each group in the
// packet's order.
//
// Spec: docs/verse_wire.md section 6 ("Order within one packet"), from r6
// v_network_out_que.c and v_cmd_buf.c.
//
// Rationale: r6's client library does not send a flush in the order its
// commands were called. v_noq_send_buf queues each command under a slot
// chosen by a hash of its address bytes (command number, node, layer,
// element: v_cmd_buf_set_address_size), a later command with the same
// address replaces the unsent earlier one, and v_noq_send_queue fills a
// packet by walking the slots round-robin from where the last packet
// stopped. So one packet from r6's client holds at most one command per
// address, in an order no client chose: a triangle can come before the
// vertices it names. r6's own host does not mind because it checks no
// reference (a MUST deviation, POLY-VERTEX-REF-1). A host that does check
// must not depend on order within a packet for commands whose addresses
// differ, and must keep the order of commands whose addresses are the
// same. The grouping below does both: creations come before their uses
// whatever the hash order (a layer before its slots, vertices before the
// polygons naming them, an element before its slots), and two commands of
// one address are in the same group, so never swapped. Packets stay in id
// order; vgc's own client sends one command per packet, so nothing it
// sends is reordered.
#pragma once

#include <vector>

#include "wire_commands.h"

namespace vgc::verse {

// 0: layer_create / layer_destroy (48); 1: vertex commands on layer 0 (50
// and 51 on layer 0, vertex_delete); 2: polygon commands on layer 1 (55 on
// layer 1, polygon_delete); 3: everything else.
int packet_order_group(const WireCommand& c);

// Stable-sorts one packet's commands by packet_order_group.
void order_packet(std::vector<WireCommand>* commands);

}  // namespace vgc::verse
