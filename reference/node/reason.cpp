// reason.cpp — see reason.h.
#include "reason.h"

namespace vgc {
namespace {
struct Entry {
  Reason reason;
  std::string_view name;
};
constexpr Entry kNames[] = {
    {Reason::Ok, "OK"},
    {Reason::NoSuchLayer, "NO_SUCH_LAYER"},
    {Reason::BaseLayer, "BASE_LAYER"},
    {Reason::BadLayerType, "BAD_LAYER_TYPE"},
    {Reason::WrongLayerType, "WRONG_LAYER_TYPE"},
    {Reason::BadName, "BAD_NAME"},
    {Reason::NameInUse, "NAME_IN_USE"},
    {Reason::NoFreeId, "NO_FREE_ID"},
    {Reason::NoSuchVertex, "NO_SUCH_VERTEX"},
    {Reason::NoSuchPolygon, "NO_SUCH_POLYGON"},
    {Reason::BadPolygon, "BAD_POLYGON"},
    {Reason::BadValue, "BAD_VALUE"},
    {Reason::BadRealFormat, "BAD_REAL_FORMAT"},
    {Reason::NoSuchBone, "NO_SUCH_BONE"},
    {Reason::BoneCycle, "BONE_CYCLE"},
    {Reason::BadWeightLayer, "BAD_WEIGHT_LAYER"},
    {Reason::BadReferenceLayer, "BAD_REFERENCE_LAYER"},
    {Reason::Limit, "LIMIT"},
};
}  // namespace

std::string_view reason_name(Reason r) {
  for (const auto& e : kNames)
    if (e.reason == r) return e.name;
  return "?";
}

bool parse_reason_name(std::string_view name, Reason* out) {
  for (const auto& e : kNames)
    if (e.name == name) {
      *out = e.reason;
      return true;
    }
  return false;
}

}  // namespace vgc
