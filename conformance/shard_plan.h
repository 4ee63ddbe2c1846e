// shard_plan.h — which shard each property runs in, and how a property
// split by case shares its cases out (certify --shard I/N).
//
// Spec: no clause; docs/certify.md "Splitting a run: shards".
//
// Rationale: a shard's findings must be the unsharded run's, and the shards
// should cost about the same: properties go whole to one shard each, by
// cost, and only a property at scale is split by case.
#pragma once

#include <vector>

namespace vgc {

// Shards by cost (RunOptions::shard_*): the shard each property of the
// catalog runs in, or -1 for a property at scale, whose cases are split
// over every shard (case k in shard k mod N; its cases cost about the same,
// scale_mesh.h). The others go whole to one shard each, so a shard's
// findings are the unsharded run's: the costliest first, each to the shard
// with the least cost so far (the split property's share counted in every
// shard), ties to the earlier property and the lower shard. Only the
// properties that will run count (`runs`: selected, claimed, runnable on
// the route), and on a route that is not run at scale (the Verse wire,
// RouteLimits::at_scale) a property costs
// its cases, each a run of round trips; PropertySpec::cost otherwise. The
// same in every shard of one implementation.
std::vector<int> assign_shards(const std::vector<bool>& runs, int count, int cases, bool wire);

// How many of `all` cases fall in shard `index` of `count`.
int shard_cases(int all, int index, int count);

}  // namespace vgc
