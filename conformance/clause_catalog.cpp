// clause_catalog.cpp — see clause.h. One entry per normative statement of
// 000 section 2.6 (and the README's protocol facts) that the suite judges.
//
// Levels follow the spec's words: MUST only where the text of 000 2.6 or a
// wire fact of the README makes it a rule; SHOULD where the text says
// "typically" (or "should"); IMPLEMENTATION-DEFINED where the text is silent,
// and then the reading says that it is the suite's reading. The r6 host's
// observed behaviour (README, last section) is "one implementation-defined
// profile, not the rule", so a clause resting on it alone is
// IMPLEMENTATION-DEFINED.
#include "clause.h"

namespace vgc {

std::string_view clause_level_name(ClauseLevel level) {
  switch (level) {
    case ClauseLevel::Must: return "MUST";
    case ClauseLevel::Should: return "SHOULD";
    case ClauseLevel::ImplementationDefined: return "IMPLEMENTATION-DEFINED";
  }
  return "?";
}

namespace {
constexpr ClauseLevel MUST = ClauseLevel::Must;
constexpr ClauseLevel SHOULD = ClauseLevel::Should;
constexpr ClauseLevel IMPL = ClauseLevel::ImplementationDefined;
}  // namespace

const std::vector<Clause>& clause_catalog() {
  static const std::vector<Clause> catalog = {
      // ---- layers (2.6.1) ------------------------------------------------------
      {"LAYER-BASE-1", "layers", MUST, "000 2.6.1",
       "The first layer, named \"vertex\" ... is always of type VN_G_LAYER_VERTEX_XYZ. The second layer ... must "
       "have type VN_G_LAYER_POLYGON_CORNER_UINT32 and be named \"polygon\". ... They are always present in every "
       "geometry node.",
       "A fresh node's snapshot lists layer 0 \"vertex\" VERTEX_XYZ and layer 1 \"polygon\" POLYGON_CORNER_UINT32, "
       "and no command sequence removes them."},
      {"LAYER-BASE-2", "layers", MUST, "000 2.6.1",
       "These two layers are rigidly defined since a host must be able to perform validity checking on them.",
       "layer_create and layer_destroy on id 0 or 1 are rejected and change nothing. (The r6 host instead "
       "allocates another id for a create on 0 or 1 and ignores a destroy; a host that ignores is seen here as "
       "rejecting, which passes.)"},
      {"LAYER-TYPE-1", "layers", MUST, "000 2.6.1, Table 2-1; README",
       "The geometry data is stored in layers, where each layer has a well-defined type. (README: any other value "
       "is not a layer type.)",
       "layer_create with a type byte outside Table 2-1's eight values is rejected."},
      {"LAYER-CREATE-1", "layers", MUST, "000 2.6.1; README (g_layer_create)",
       "Any other layers can have whatever type is required by the application.",
       "layer_create on a free id from 2 to 0xFFFE, with a valid type and name, creates the layer with the name, "
       "type and defaults sent."},
      {"LAYER-STACK-1", "layers", MUST, "000 2.6.1",
       "Other layers, when created, will end up in one of the stacks depending on whether it is a vertex or "
       "polygon layer.",
       "A layer of type VERTEX_* has one slot per live vertex, a layer of type POLYGON_* one per live polygon."},
      {"LAYER-SIZE-1", "layers", MUST, "000 2.6.1",
       "The size of all layers in a stack is controlled by the size of the base layer of that stack ... all "
       "other layers are grown to provide a slot of data space ... for the new addition.",
       "After every command, every layer has exactly one slot for each live element of its stack's base layer: "
       "creating a vertex or polygon adds a slot to every layer of its stack, deleting one removes it."},
      {"LAYER-DEFAULT-1", "layers", SHOULD, "000 2.6.1; README (def_uint, def_real)",
       "This slot is typically initialized with a default value, to make it well-defined until explicitly set.",
       "SHOULD, because the spec says \"typically\". A new slot takes its layer's default: def_uint for integer "
       "layers (POLYGON_FACE_UINT8 keeps its low 8 bits, the suite's reading of a uint32 default on a uint8 "
       "layer), def_real for real and XYZ layers, in every component. This holds for slots made when an element "
       "is created and when a layer is created over existing elements. Only the default a layer's type uses is "
       "compared on its snapshot line (docs/commands.md 6.1)."},
      {"LAYER-NAME-1", "layers", MUST, "README (r6 protocol)",
       "Names ... at most 16 bytes including the terminating NUL, so 15 visible bytes.",
       "layer_create with a name over 15 bytes or holding a NUL byte is rejected. (An empty name is the "
       "protocol's destroy; see LAYER-DESTROY-1.)"},
      {"LAYER-NAME-2", "layers", IMPL, "000 2.6.2, 2.6.3 (layers are referenced by name)",
       "... crease information can be stored in a layer and referenced that way. / By specifying the name of a "
       "VN_G_LAYER_VERTEX_UINT32 layer ...",
       "The spec does not say whether names are unique; this is the suite's reading. Creases and bones name "
       "layers, so names are unique within a node: layer_create with a name another layer "
       "has is rejected and changes nothing. Latitude: none beyond that; the r6 host silently ignores such a "
       "create, which is the same observable outcome."},
      {"LAYER-RECREATE-1", "layers", IMPL, "README (r6 behaviour); 000 2.6.1",
       "(silent) Creating on an existing id with a new type re-types it and resets its data (r6).",
       "The spec is silent; this is the suite's reading (the r6 host's, for another type). layer_create on a "
       "live non-base layer id replaces its name and defaults. Same type: slot values are kept. "
       "Other type: the layer moves to its new type's stack and every slot takes the new default."},
      {"LAYER-DESTROY-1", "layers", MUST, "README (g_layer_destroy)",
       "48 g_layer_create(...); an empty name means g_layer_destroy(layer_id).",
       "Destroying a live non-base layer removes it and all its data; its id and name can be used again. "
       "Destroying an id with no layer is rejected."},
      {"LAYER-ID-PICK-1", "layers", IMPL, "README (r6 protocol)",
       "An id of 0xFFFFFFFF (vertex, polygon) or 0xFFFF (layer, bone) in a create/set command asks the host to "
       "pick a free id.",
       "layer_create with id 0xFFFF creates the layer at a free id (the wire fact). Which free id, the spec "
       "does not say (\"a free id\"): the suite's reading is the lowest free id from 2 up, so that two "
       "implementations fed the same commands agree on ids."},
      {"LAYER-SUBSCRIBE-1", "layers", MUST, "README (g_layer_subscribe); 000 2.6.1",
       "Real format of a subscription: REAL32=0, REAL64=1. / 49 g_layer_subscribe(layer_id, real_format); a "
       "real_format above REAL64 (any value > 1) means g_layer_unsubscribe(layer_id).",
       "layer_subscribe to a live layer with REAL32 or REAL64 is applied and recorded; with any other format it "
       "is the unsubscribe (the same bytes on the wire); layer_unsubscribe of a live layer is applied and "
       "clears the subscription; either on a missing layer is rejected."},
      {"LAYER-WRITE-1", "layers", MUST, "000 2.6.1, Table 2-1; README (command set)",
       "The geometry data is stored in layers, where each layer has a well-defined type.",
       "A value command is accepted only on a layer of the type it is for (vertex_set_uint32 on VERTEX_UINT32, "
       "polygon_set_face_real64 on POLYGON_FACE_REAL, ...), and only for a live vertex or polygon; otherwise it "
       "is rejected. It never creates an element."},
      {"LAYER-VALUE-1", "layers", MUST, "000 2.6.1, Table 2-1",
       "Values per Index: 3 (XYZ), 1 (VERTEX_UINT32, VERTEX_REAL, POLYGON_FACE_*), 4 (POLYGON_CORNER_*).",
       "A value written to a slot is read back exactly: all components, the uint8 range of POLYGON_FACE_UINT8."},
      {"REAL-STORAGE-1", "layers", MUST, "000 2.6.1",
       "The REAL-typed layers ... always occupy 64 bits in the host memory.",
       "A real64 write is stored bit for bit, NaN payloads and -0.0 included."},
      {"REAL-32BIT-1", "layers", MUST, "000 2.6.1",
       "The REAL-typed layers can be read and written using either 32 or 64 bits by clients.",
       "A real32 write stores the float converted exactly to 64 bits: the same as the real64 write of that "
       "float's value."},

      // ---- vertices --------------------------------------------------------------
      {"VERTEX-SET-1", "vertices", MUST, "000 2.6.1",
       "As vertices ... are created, the defining data (the XYZ coordinates ...) are placed in a slot in the "
       "base layer.",
       "vertex_set_xyz_real32/64 on layer 0 creates the vertex at a new id and moves a live one; a moved vertex "
       "keeps its slot values in every other vertex-stack layer (docs/commands.md 4.5 step 4)."},
      {"VERTEX-DELETE-1", "vertices", MUST, "README (r6 protocol)",
       "x, y or z equal to FLT_MAX means g_vertex_delete_real32(vertex_id); DBL_MAX means "
       "g_vertex_delete_real64(vertex_id).",
       "A set with a max-valued coordinate, whatever layer it names (the same bytes as the delete on the "
       "wire), or vertex_delete deletes the vertex from every vertex layer; deleting a vertex that is not live "
       "is rejected."},
      {"VERTEX-ID-PICK-1", "vertices", IMPL, "README (r6 protocol)",
       "An id of 0xFFFFFFFF (vertex, polygon) ... asks the host to pick a free id.",
       "A set on layer 0 (1) with id 0xFFFFFFFF creates the vertex (polygon) at a free id (the wire fact). "
       "Which free id, the spec does not say: the suite's reading is the lowest free id, for vertices and "
       "polygons alike."},
      {"VERTEX-FINITE-1", "vertices", IMPL, "000 2.6 (vertex data describe positions)",
       "Vertex data describe positions in a local 3D space.",
       "The spec is silent on non-finite coordinates; this is the suite's reading. A base-layer position with "
       "an infinite or NaN coordinate is rejected (it is not a position, and it cannot be subdivided). Other "
       "VERTEX_XYZ layers hold any value."},
      {"ID-BOUND-1", "vertices", MUST, "README (id widths)",
       "Identifier widths: ... vertex id and polygon id uint32.",
       "Any id up to 0xFFFFFFFE can be used directly, without the host allocating storage for the ids below it: "
       "a command on vertex 4000000000 answers within the call time limit like any other."},

      // ---- polygons --------------------------------------------------------------
      {"POLY-CORNERS-1", "polygons", MUST, "000 2.6",
       "All polygons have exactly three or four corners (vertex references), there is no support for general "
       "N-sided polygons.",
       "A polygon_set_corner_uint32 on layer 1 whose first three corners are not all vertex references "
       "(0xFFFFFFFF among them) is rejected."},
      {"POLY-TRIANGLE-1", "polygons", MUST, "000 2.6",
       "There is always storage reserved for four corners for a given polygon; if the three first references "
       "are valid and the fourth unused, the polygon is a triangle. If also the fourth reference is to a valid "
       "vertex, it is a quadrilateral.",
       "Triangles (fourth corner 0xFFFFFFFF) and quads are created and re-defined with the corners as sent; a "
       "re-defined polygon keeps its slot values in every other polygon-stack layer (docs/commands.md 4.5 step 5)."},
      {"POLY-VERTEX-REF-1", "polygons", MUST, "000 2.6",
       "... polygons are created by referencing the vertices. All polygons have exactly three or four corners "
       "(vertex references) ... if the three first references are valid and the fourth unused, the polygon is "
       "a triangle. If also the fourth reference is to a valid vertex, it is a quadrillion.",
       "A corner that names no live vertex is rejected. (The r6 host does not check this.)"},
      {"POLY-DISTINCT-1", "polygons", IMPL, "README (r6 behaviour)",
       "(silent) Polygon corners must be pairwise distinct (README, \"How the real r6 host behaves where the "
       "text is silent\": \"one implementation-defined profile, not the rule\").",
       "000 2.6 does not say whether a corner may repeat; this is the suite's reading, the r6 host's check: a "
       "polygon with a repeated corner is rejected."},
      {"POLY-DELETE-1", "polygons", MUST, "README (r6 protocol)",
       "55 g_polygon_set_corner_uint32(...); on layer 1 with v0 = 0xFFFFFFFF it means g_polygon_delete(polygon_id).",
       "Deleting a live polygon removes it from every polygon layer; deleting one that is not live is rejected."},
      {"POLY-VERTEX-DELETE-1", "polygons", IMPL, "000 2.6 (silent)",
       "(silent) What happens to polygons when a vertex they use is deleted.",
       "The spec is silent; this is the suite's reading. The vertex is deleted and so is every polygon that "
       "uses it, so every live polygon always names "
       "live vertices. (The r6 host leaves such polygons dangling, which this suite does not accept: a dangling "
       "polygon is not a valid polygon.)"},

      // ---- creases (2.6.2) ---------------------------------------------------------
      {"CREASE-DEFAULT-1", "creases", MUST, "000 2.6.2",
       "... either they can all be set to a single constant, or crease information can be stored in a layer.",
       "crease_set_vertex / crease_set_edge with an empty layer name make the constant the crease of every "
       "vertex / every polygon edge."},
      {"CREASE-VERTEX-LAYER-1", "creases", MUST, "000 2.6.2",
       "If a layer is used, it must be of type VN_G_LAYER_VERTEX_UINT32 for vertex creases.",
       "With a VERTEX_UINT32 layer named, each vertex's crease is its slot in that layer."},
      {"CREASE-EDGE-LAYER-1", "creases", MUST, "000 2.6.2; README",
       "... each corner holds the crease data for the edge that starts in that corner. (README: corner i holds "
       "the crease of the edge from corner i to corner i+1, wrapping to 0; for a triangle, corner 2 wraps to "
       "corner 0.)",
       "With a POLYGON_CORNER_UINT32 layer named, the crease of polygon p's edge from corner i is slot p, "
       "component i; a triangle has three edges, a quad four."},
      {"CREASE-LAYER-MISSING-1", "creases", IMPL, "000 2.6.2 (silent)",
       "If a layer is used, it must be of type VN_G_LAYER_VERTEX_UINT32 ... and VN_G_LAYER_POLYGON_CORNER_UINT32 "
       "for edges.",
       "The spec is silent on a name that names no such layer; this is the suite's reading. The name is stored "
       "as sent and resolved when creases are read; while it names no layer, or a "
       "layer of another type, the constant def_crease applies. So a crease layer may be created after it is "
       "named."},
      {"CREASE-INITIAL-1", "creases", IMPL, "000 2.6.4",
       "To make sure the cube is not interpreted as a smooth shape, we need to explicitly set the creasing to "
       "\"sharp\".",
       "The spec does not give a new node's creases; this is the suite's reading, from the cube needing them "
       "set \"explicitly\": a new node is smooth everywhere (both creases the constant 0)."},
      {"CREASE-NAME-1", "creases", MUST, "README (names)",
       "Names (layer names, crease layer names, ...): at most 16 bytes including the terminating NUL.",
       "A crease layer name over 15 bytes or holding a NUL is rejected."},

      // ---- bones (2.6.3) ---------------------------------------------------------
      {"BONE-CREATE-1", "bones", MUST, "000 2.6.3",
       "... each bone having a numerical ID, a parent ID, weight and reference layer pointers, a position, a "
       "position curve pointer, a rotation and a rotation curve pointer.",
       "bone_create stores every field as sent; on a live id it replaces them."},
      {"BONE-DESTROY-1", "bones", MUST, "README (g_bone_destroy)",
       "an empty weight name means g_bone_destroy(bone_id).",
       "Destroying a live bone removes it; destroying an id with no bone is rejected; the id can be used again."},
      {"BONE-WEIGHT-1", "bones", MUST, "000 2.6.3",
       "Such layers must be of type VN_G_LAYER_VERTEX_UINT32 or VN_G_LAYER_VERTEX_REAL.",
       "bone_create whose weight layer name names no layer, or a layer of another type, is rejected. Reading: "
       "checked when the bone is created; a later destroy or re-type of the layer is allowed."},
      {"BONE-REFERENCE-1", "bones", IMPL, "000 2.6.3",
       "By specifying the name of a VN_G_LAYER_VERTEX_UINT32 layer in the reference field of a bone, this "
       "secondary system is triggered. The layer should contain bone IDs ...",
       "The spec says what naming a VERTEX_UINT32 layer does, not what naming anything else does; this is the "
       "suite's reading: a non-empty reference name must name a VERTEX_UINT32 layer when the bone is created, "
       "otherwise bone_create is rejected."},
      {"BONE-PARENT-1", "bones", MUST, "000 2.6.3",
       "It can be set to a non-existing bone to indicate that no parent exists, and the bone will then be at root "
       "level.",
       "A bone whose parent id names no live bone is a root: its bone_pose line is its own position as stored and "
       "its rotation normalized (docs/commands.md 4.8: scaled to unit length; the reference prints it with w >= 0). "
       "Compared as every bone_pose line is: each of the three position numbers, and the four rotation numbers "
       "either as they are or all negated (q and -q are one rotation), within 1e-9 times the larger of 1 and the "
       "two numbers' magnitudes. So a root's rotation must be of unit length; its sign is free."},
      {"BONE-FOREST-1", "bones", IMPL, "000 2.6.3 (silent)",
       "The parent link defines hierarchies of bones, i.e. skeletons.",
       "The spec is silent on cycles; this is the suite's reading. \"Hierarchies\" rules out a cycle among "
       "the bones a node holds, but 2.6.3 does not say what a host does with a bone_create whose link would "
       "close one: reject it, store the bone at root level (as for a parent that does not exist), or store "
       "it as sent (the r6 host). The suite rejects it, so bones always form a forest; a host that does "
       "otherwise is a profile difference, gating with --strict."},
      {"BONE-DOWNSTREAM-1", "bones", MUST, "000 2.6.3",
       "The geometry node can also store local transformations known as bones. ... if you rotate any bone, all "
       "bones \"downstream\" of it will rotate, too.",
       "World poses (derived document): a bone's position and rotation are relative to its parent's frame; "
       "world_rot = parent_rot * rot, world_pos = parent_pos + parent_rot applied to pos (bone_pose.h). Checked "
       "within 1e-9 relative."},
      {"BONE-VALUE-1", "bones", IMPL, "000 2.6.3 (silent)",
       "... a position ... a rotation ...",
       "The spec is silent on non-finite or zero poses; this is the suite's reading. A non-finite position or "
       "rotation component, or the zero quaternion, is rejected, so every bone has a pose."},
      {"BONE-ID-PICK-1", "bones", SHOULD, "README (r6 protocol); 000 2.6.3",
       "An id of ... 0xFFFF (layer, bone) in a create/set command asks the host to pick a free id. / Bones are "
       "typically numbered from zero and upwards, and the sequence of IDs will typically be kept \"tight\", "
       "with as few gaps of unused IDs as possible.",
       "bone_create with id 0xFFFF creates the bone at a free id; SHOULD, because the spec says \"typically\", "
       "that id is the lowest free one from 0 up, which keeps the ids tight."},
      {"BONE-NAME-1", "bones", MUST, "README (names)",
       "Names (... bone weight/reference layer names, curve labels): at most 16 bytes including the terminating "
       "NUL.",
       "A weight, reference or curve label over 15 bytes or holding a NUL is rejected."},

      // ---- commands as a whole ---------------------------------------------------
      {"ATOMIC-1", "commands", MUST, "README (r6 protocol)",
       "Hosts on the wire send no acknowledgement and no error: a command is applied (and re-broadcast to "
       "subscribers) or dropped silently.",
       "A rejected command changes nothing observable: snapshot and derived documents are as before it."},
      {"ACCEPT-1", "commands", MUST, "README (command set)",
       "Command set of the geometry node, with protocol command numbers 48..64.",
       "Every command in canonical text form is understood: answered ok, rejected or done, never 'error'; every "
       "command the spec allows is applied (failures of a specific rule are attributed to that rule's clause)."},
      {"REASON-1", "commands", SHOULD, "suite (docs/commands.md, reason codes)",
       "(silent) The r6 host reports no errors to the client.",
       "A rejection names the reason code the reference gives (reason.h). Mismatches are reported but do not "
       "change the verdict. Not applicable to a step the implementation answered `done` (a verdict it does "
       "not report, as a host on the wire cannot: docs/adapters.md)."},
      {"STABLE-1", "commands", MUST, "suite (adapter contract, docs/adapters.md)",
       "(silent) An implementation answers every call.",
       "The implementation neither crashes nor hangs on any command sequence; a crash or timeout is attributed "
       "to the clause of the command it happened on and recorded with a reproducer."},
      {"MESH-CLASSIFY-1", "derived", MUST, "002 (winged edge, manifold rules); optional capability \"manifold\"",
       "\"Each edge in the polygon mesh can be the edge of either one or two polygons\"; the neighbourhood of "
       "every point is \"topologically equivalent to a disc ... or a half disc\".",
       "MUST when claimed (?capabilities names \"manifold\"), not claimed otherwise. The ?classify answer on "
       "the node's live polygons agrees with CGAL Polygon Mesh Processing: polygon_mesh with "
       "is_polygon_soup_a_polygon_mesh; for a polygon mesh closed, oriented, euler (V - E + F, vertices in no "
       "polygon not counted), components and boundary_loops with the Surface_mesh CGAL builds from it "
       "(definitions of reference/geometry/mesh_topology.h; docs/adapters.md \"Optional capabilities\")."},
      {"SUBD-CATMARK-1", "derived", MUST, "000 2.6; optional capability \"subdivision\"",
       "\"Verse has a single primitive ...: Catmull/Clark subdivision surfaces\" with \"creases with which one "
       "can control the degree of subdivision allowed for each vertex and edge\".",
       "MUST when claimed (?capabilities names \"subdivision\"), not claimed otherwise. The ?subdivide N "
       "vertices (N = 1..3) agree with OpenSubdiv Catmark refinement of the node's polygons (uniform creasing, "
       "edge-only boundaries, the crease-to-sharpness mapping of reference/geometry/crease_sharpness.h) as a bijection "
       "within 1e-9 of the coordinate scale, and the vertex and face counts agree. Compared on every mesh the node "
       "can hold, non-manifold included, with OpenSubdiv's non-manifold rules: an edge of more than two polygons, "
       "or of two polygons running the same direction, is infinitely sharp, and a non-manifold vertex (on such "
       "an edge, or where two fans meet: a bow-tie) is an infinitely sharp corner except on an interior "
       "non-manifold crease (reference/geometry/catmull_clark.h); where OpenSubdiv refuses the polygons the case is not "
       "judged. Vertices in no polygon are left out."},
      {"NORMALS-SPLIT-1", "normals", MUST, "003 (split vertex normals); optional capability \"normals\"",
       "\"A sharp edge is either tagged as such, non-manifold (i.e. used by more or less than exactly two faces), "
       "and/or manifold but used by two faces having opposed normals\"; \"Smooth fan: a set of loops sharing the "
       "same vertex, and belonging to faces joined by smooth edges only\"; \"Each smooth fan has only one "
       "automatically-computed loop normal\".",
       "MUST when claimed (?capabilities names \"normals\"), not claimed otherwise. ?normals gives one normal per "
       "corner of every live polygon. Checked from spec 003 itself: the corners at either end of a smooth edge "
       "(two polygons, opposite directions, no corner holding edge crease 0xFFFFFFFF: the tag, 000 2.6.2) have "
       "one normal, and a corner between two sharp edges has its polygon's unit front normal (Newell, clockwise "
       "front). No external oracle is linked for the fan normal itself: every corner is compared with "
       "reference/geometry/split_normals.h (angle-weighted sum of the fan's face normals, normalized). All within 1e-9; "
       "not compared where the reference cannot give the polygons normals or a polygon's vertex has a "
       "coordinate beyond 1e60 in magnitude (its normal's length overflows a double)."},
      {"LOOP-TRIANGLE-1", "loop", MUST, "004 (MeshEd triangle tree); optional capability \"loop\"",
       "\"TTree* children[4]\"; \"We have affectionate names for the children; we call them T0, T1, T2, and "
       "T3\"; \"Sub-triangles are named according to their nearest vertex, with T0 in the center\"; \"Edges are "
       "named for their opposite vertex\"; \"Sub-vertices are named for their opposite vertex.\"",
       "MUST when claimed (?capabilities names \"loop\"), not claimed otherwise. When every live polygon is a "
       "triangle, the ?subdivide-loop N vertices (N = 1..3) agree with OpenSubdiv's Loop scheme (uniform creasing, "
       "edge-only boundaries, the crease mapping of reference/geometry/crease_sharpness.h) as a bijection within 1e-9 of "
       "the coordinate scale, with the vertex and face counts; and the face lines are the triangle tree, built "
       "on OpenSubdiv's levels: children T0..T3 of each parent consecutively, T0 = [s0 s1 s2] the centre, "
       "T(j+1) = [vj' s(j+2) s(j+1)] nearest vertex j, sk the child of the edge opposite vertex k (the oriented "
       "order of reference/geometry/loop_subdivision.h; the spec's figure is not part of it). Compared on every "
       "all-triangle mesh the node can hold, non-manifold included (OpenSubdiv's non-manifold rules as for "
       "SUBD-CATMARK-1; each level's edges come from its parent's edges and faces, so two triangles on the same "
       "three vertices keep distinct child edges); where OpenSubdiv refuses the polygons the case is not judged. "
       "When a live polygon is a quad the answer is one line \"error ...\"."},
      {"EDIT-HIERARCHY-1", "edits", MUST, "001 (hierarchical edits); optional capability \"edits\"",
       "\"A hierarchical edit is an edit made to any one of the faces, edges, or vertices that arise anywhere "
       "during subdivision\"; \"'set' indicates the primitive variable value ... is to be set directly\"; \"'add' "
       "adds a value to the normal result computed via standard subdivision rules\"; \"The faces will be deleted, "
       "and none of their children will appear\".",
       "MUST when claimed (?capabilities names \"edits\"), not claimed otherwise. ?subdivide-edit N <edit> (N = "
       "1..3; edits hole, set, add on a path of spec 001 with the polygon id as the base face, paths to level 3) "
       "answers the Catmull-Clark refinement with the edit, its face lines the faces that are not holes. Each "
       "case draws one edit. Checked against OpenSubdiv Catmark: a hole at level 0 against OpenSubdiv's holes "
       "(vertices, kept faces); a deeper hole moves nothing and removes exactly its 4^(N - k) descendants, the "
       "rest OpenSubdiv's faces; add 0 changes nothing; the level above an edit at level k >= 2 is the plain "
       "refinement; at the edit's own level exactly one vertex moves and set puts it at the value (where coordinates are "
       "at most 1e6, so that the tolerance is far below the move). OpenSubdiv 3 "
       "has no hierarchical edits, so where the edit moves vertices (set, add at levels above N) the vertices "
       "are compared with reference/geometry/hierarchical_edit.h only (its decisions: an edit applies after its level is "
       "computed, before the next). Vertices as a bijection within 1e-9 of the coordinate scale; compared on every "
       "mesh the node can hold, non-manifold included; not judged where OpenSubdiv refuses the polygons."},
  };
  return catalog;
}

const Clause* find_clause(std::string_view id) {
  for (const auto& c : clause_catalog())
    if (c.id == id) return &c;
  return nullptr;
}

}  // namespace vgc
