// route_test.cpp — an --impl value read once into a Route (route.h): each
// form's kind, target and traits; the messages for a value that names no
// route; and that no product file outside the route parser tests a route's
// prefix again (issue 29, "no route prefix tested outside the route
// parser").
//
// Spec: docs/adapters.md (the routes), docs/certify.md (--impl).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "route.h"

namespace vgc {
namespace {

Route parsed(const std::string& spec) {
  std::string error;
  const std::optional<Route> r = parse_route(spec, &error);
  EXPECT_TRUE(r.has_value()) << spec << ": " << error;
  return r.value_or(Route{});
}

std::string refused(const std::string& spec) {
  std::string error;
  EXPECT_FALSE(parse_route(spec, &error).has_value()) << spec;
  return error;
}

TEST(Route, EachFormIsReadIntoItsKindAndTarget) {
  const Route ref = parsed("reference");
  EXPECT_EQ(ref.kind, RouteKind::Reference);
  EXPECT_EQ(ref.spec, "reference");

  const Route exec = parsed("exec:./my host --serve");
  EXPECT_EQ(exec.kind, RouteKind::Exec);
  EXPECT_EQ(exec.target, "./my host --serve");
  EXPECT_EQ(exec.spec, "exec:./my host --serve");  // the name in reports, as given

  const Route plugin = parsed("plugin:/x/libnode.so");
  EXPECT_EQ(plugin.kind, RouteKind::Plugin);
  EXPECT_EQ(plugin.target, "/x/libnode.so");

  const Route verse = parsed("verse:alice@10.0.0.7:4951");
  EXPECT_EQ(verse.kind, RouteKind::Verse);
  EXPECT_EQ(verse.login, "alice");
  EXPECT_EQ(verse.host, "10.0.0.7");
  EXPECT_EQ(verse.port, 4951);
  const Route verse_default = parsed("verse:localhost");
  EXPECT_EQ(verse_default.login, "vgc");
  EXPECT_EQ(verse_default.port, 4950);
}

TEST(Route, TraitsSayWhatEachRouteCanDo) {
  const RouteTraits& ref = parsed("reference").traits();
  EXPECT_TRUE(ref.in_process && ref.restartable && ref.derived_documents && ref.reports_verdicts &&
              ref.answers_requests);
  const RouteTraits& exec = parsed("exec:prog").traits();
  EXPECT_FALSE(exec.in_process);
  EXPECT_TRUE(exec.restartable && exec.derived_documents && exec.reports_verdicts && exec.answers_requests);
  EXPECT_FALSE(exec.declares_bone_form);
  const RouteTraits& plugin = parsed("plugin:lib.so").traits();
  EXPECT_TRUE(plugin.in_process && plugin.restartable);
  // A host on the wire: a server vgc did not start, stored state only, no
  // acknowledgements, no requests; it declares the bone form it speaks.
  const RouteTraits& verse = parsed("verse:localhost").traits();
  EXPECT_FALSE(verse.in_process || verse.restartable || verse.derived_documents || verse.reports_verdicts ||
               verse.answers_requests);
  EXPECT_TRUE(verse.declares_bone_form);
}

TEST(Route, AValueThatNamesNoRouteSaysTheFormsThereAre) {
  for (const std::string spec : {"", "refrence", "dll:/x.so", "Exec:prog", " exec:prog"}) {
    const std::string e = refused(spec);
    EXPECT_NE(e.find("unknown implementation '" + spec + "'"), std::string::npos) << e;
    EXPECT_NE(e.find(route_forms()), std::string::npos) << e;
  }
  EXPECT_NE(refused("exec:").find("'exec:' names no command"), std::string::npos);
  EXPECT_NE(refused("exec: \t").find("names no command"), std::string::npos);
  EXPECT_NE(refused("plugin:").find("'plugin:' names no library"), std::string::npos);
  EXPECT_NE(refused("verse:").find("no host named"), std::string::npos);
  EXPECT_NE(refused("verse:host:0").find("is not a port"), std::string::npos);
  for (const char* bad : {"verse:host:+80", "verse:host:80x", "verse:host:65536", "verse:host:99999999999999999999"})
    EXPECT_NE(refused(bad).find("is not a port"), std::string::npos) << bad;
  for (const char* form : {"reference", "exec:CMD", "plugin:PATH", "verse:[NAME@]HOST[:PORT]"})
    EXPECT_NE(route_forms().find(form), std::string::npos) << form;
}

TEST(Route, EveryRowOfTheRegistryReadsBackWhatItWrites) {
  for (const RouteEntry& e : route_registry()) {
    const std::string spec = route_spec(e.kind, "target");
    const Route r = parsed(spec);
    EXPECT_EQ(r.kind, e.kind) << spec;
    EXPECT_EQ(r.spec, spec);
    EXPECT_STREQ(r.form(), e.form);
    EXPECT_NE(e.open, nullptr) << e.form;
  }
}

// The product folders (tools/include_graph.py's layers) hold no route
// prefix outside the registry: no "exec:" / "plugin:" / "verse:" literal
// tested with rfind, compare or starts_with, cut off with substr, or
// written in front of a target. Seen failing on the tree before the route
// value (16 tests in 7 files: fuzz/campaign/campaign.cpp, cli/open_impl.cpp, ...).
TEST(Route, NoRoutePrefixIsTestedOutsideTheRouteParser) {
  namespace fs = std::filesystem;
  const fs::path root = VGC_SOURCE_DIR;
  const std::regex literal(R"re("(exec|plugin|verse):")re");
  std::vector<std::string> found;
  for (const char* folder : {"runtime", "reference", "verse", "conformance", "oracles", "fuzz", "bench", "cli"}) {
    if (!fs::is_directory(root / folder)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(root / folder)) {
      const std::string ext = entry.path().extension().string();
      if (ext != ".cpp" && ext != ".h" && ext != ".c") continue;
      if (entry.path().filename() == "route.cpp") continue;  // the registry itself
      std::ifstream in(entry.path());
      std::string line;
      for (int number = 1; std::getline(in, line); ++number) {
        const std::string code = line.substr(0, line.find("//"));  // comments may name a route
        if (std::regex_search(code, literal))
          found.push_back(fs::relative(entry.path(), root).string() + ":" + std::to_string(number) + ": " + line);
      }
    }
  }
  std::string all;
  for (const auto& f : found) all += f + "\n";
  EXPECT_TRUE(found.empty()) << "route prefixes outside conformance/adapter/route.cpp:\n" << all;
}

}  // namespace
}  // namespace vgc
