// property_catalog.cpp — see property.h.
#include "property.h"

#include <algorithm>

namespace vgc {

const std::vector<PropertySpec>& property_catalog() {
  static const std::vector<PropertySpec> catalog = {
      {"layers.stateful", "layer create, re-create, destroy and subscribe while both stacks grow and shrink",
       Focus::Layers,
       {"LAYER-BASE-1", "LAYER-BASE-2", "LAYER-TYPE-1", "LAYER-CREATE-1", "LAYER-STACK-1", "LAYER-SIZE-1",
        "LAYER-DEFAULT-1", "LAYER-NAME-1", "LAYER-NAME-2", "LAYER-RECREATE-1", "LAYER-DESTROY-1",
        "LAYER-SUBSCRIBE-1", "LAYER-WRITE-1"}, {}, false, 0.2},
      {"polygons.stateful", "vertices and polygons: corners, triangles and quads, deletion and its cascade",
       Focus::Polygons,
       {"VERTEX-SET-1", "VERTEX-DELETE-1", "VERTEX-FINITE-1", "POLY-CORNERS-1", "POLY-TRIANGLE-1",
        "POLY-VERTEX-REF-1", "POLY-DISTINCT-1", "POLY-DELETE-1", "POLY-VERTEX-DELETE-1", "REAL-32BIT-1"}, {}, false, 0.2},
      {"creases.stateful", "crease constants and crease layers, the corner-to-edge rule, missing layers",
       Focus::Creases,
       {"CREASE-DEFAULT-1", "CREASE-VERTEX-LAYER-1", "CREASE-EDGE-LAYER-1", "CREASE-LAYER-MISSING-1",
        "CREASE-INITIAL-1", "CREASE-NAME-1"}, {}, false, 0.2},
      {"bones.stateful", "bones: weight and reference layers, parents, cycles, world poses downstream",
       Focus::Bones,
       {"BONE-CREATE-1", "BONE-DESTROY-1", "BONE-WEIGHT-1", "BONE-REFERENCE-1", "BONE-PARENT-1", "BONE-FOREST-1",
        "BONE-DOWNSTREAM-1", "BONE-VALUE-1", "BONE-NAME-1"}, {}, false, 0.2},
      {"values.stateful", "values of every layer type, NaN payloads, -0.0, real32 and real64 writes",
       Focus::Values, {"LAYER-VALUE-1", "REAL-STORAGE-1", "REAL-32BIT-1", "LAYER-WRITE-1"}, {}, false, 0.2},
      {"ids.stateful", "\"pick an id\" for layers, vertices, polygons and bones; very large ids", Focus::Ids,
       {"LAYER-ID-PICK-1", "VERTEX-ID-PICK-1", "BONE-ID-PICK-1", "ID-BOUND-1"}, {}, false, 0.2},
      {"commands.atomic", "any command on any state: applied whole or rejected with nothing changed",
       Focus::Anything, {"ATOMIC-1", "ACCEPT-1", "REASON-1", "STABLE-1"}, {}, false, 0.2},
      {"storage.scale",
       "meshes of 10^4 to 10^5 elements (grids, tori, fans, ids over the whole id range) with edits interleaved",
       Focus::Polygons,
       {"VERTEX-SET-1", "VERTEX-DELETE-1", "ID-BOUND-1", "CREASE-VERTEX-LAYER-1", "CREASE-EDGE-LAYER-1"},
       {},
       true,
       18.0},
      {"derived.manifold", "optional capability: ?classify agrees with CGAL on the node's polygons",
       Focus::Polygons, {"MESH-CLASSIFY-1"}, "manifold", false, 1.2},
      {"derived.subdivision", "optional capability: ?subdivide agrees with OpenSubdiv Catmark, creases included",
       Focus::Creases, {"SUBD-CATMARK-1"}, "subdivision", false, 0.6},
      {"derived.normals", "optional capability: ?normals gives spec 003 split normals, sharp edges from max creases",
       Focus::Creases, {"NORMALS-SPLIT-1"}, "normals", false, 0.4},
      {"derived.loop", "optional capability: ?subdivide-loop agrees with OpenSubdiv Loop; the spec 004 triangle tree",
       Focus::Creases, {"LOOP-TRIANGLE-1"}, "loop", false, 1.0},
      {"derived.edits", "optional capability: ?subdivide-edit applies a spec 001 hierarchical edit (drawn per case)",
       Focus::Creases, {"EDIT-HIERARCHY-1"}, "edits", false, 3.0},
  };
  return catalog;
}

int property_cases(const PropertySpec& spec, int cases) {
  if (spec.at_scale) return std::max(2, cases / 50);
  return spec.capability.empty() ? cases : std::max(1, cases / 4);
}

const PropertySpec* find_property(std::string_view id) {
  for (const auto& p : property_catalog())
    if (p.id == id) return &p;
  return nullptr;
}

}  // namespace vgc
