// shard_plan.cpp — see shard_plan.h.
#include "shard_plan.h"

#include <algorithm>
#include <cstddef>

#include "property.h"

namespace vgc {

std::vector<int> assign_shards(const std::vector<bool>& runs, int count, int cases, bool wire) {
  const auto& props = property_catalog();
  std::vector<int> shard(props.size(), 0);
  if (count <= 1) return shard;
  auto cost = [&](std::size_t i) {
    return wire ? static_cast<double>(property_cases(props[i], cases)) : props[i].cost;
  };
  std::vector<double> load(static_cast<std::size_t>(count), 0.0);
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < props.size(); ++i) {
    if (!props[i].at_scale) {
      order.push_back(i);
      continue;
    }
    shard[i] = -1;
    if (!runs[i]) continue;
    const int all = property_cases(props[i], cases);
    for (int k = 0; k < count; ++k)
      load[static_cast<std::size_t>(k)] += cost(i) * shard_cases(all, k, count) / all;
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return (runs[a] ? cost(a) : 0.0) > (runs[b] ? cost(b) : 0.0);
  });
  for (std::size_t i : order) {
    const auto least = static_cast<std::size_t>(std::min_element(load.begin(), load.end()) - load.begin());
    if (runs[i]) load[least] += cost(i);
    shard[i] = static_cast<int>(least);
  }
  return shard;
}

// How many of `all` cases fall in shard `index` of `count`.
int shard_cases(int all, int index, int count) {
  if (count <= 1) return all;
  return all / count + (index < all % count ? 1 : 0);
}

}  // namespace vgc
