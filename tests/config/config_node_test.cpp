#include "config/config_node.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>

namespace iga {
namespace {

const char* kQuick =
    "problem:\n"           // line 1
    "  pde: poisson\n"     // line 2
    "domain:\n"            // line 3
    "  min: [0, 1.5]\n"    // line 4
    "  max: [1, abc]\n"    // line 5
    "space:\n"             // line 6
    "  degre: 3\n"         // line 7
    "  kind: bsplin\n"     // line 8
    "  degree: three\n"    // line 9
    "  levels: 2.5\n"      // line 10
    "  count: 4\n"         // line 11
    "  flag: yes\n"        // line 12
    "  ints: [1, 2, 3]\n"  // line 13
    "  empty:\n"           // line 14
    "  neg: -7\n";         // line 15

/// The message of the InputError thrown by `f` (fails the test when nothing or something else is thrown).
std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected InputError, got: " << e.what();
    return {};
  }
  ADD_FAILURE() << "expected InputError, nothing thrown";
  return {};
}

TEST(ConfigNode, PathsAndTypedValues) {
  ConfigNode root = ConfigNode::load_string(kQuick, "quick.yaml");
  EXPECT_EQ(root.path(), "");
  EXPECT_TRUE(root.is_map());
  EXPECT_EQ(root.keys(), (std::vector<std::string>{"problem", "domain", "space"}));

  ConfigNode space = root["space"];
  EXPECT_EQ(space.path(), "space");
  EXPECT_EQ(space["count"].path(), "space.count");
  EXPECT_EQ(space["count"].as_int(), 4);
  EXPECT_EQ(space["neg"].as_int(), -7);
  EXPECT_DOUBLE_EQ(space["levels"].as_double(), 2.5);
  EXPECT_DOUBLE_EQ(space["count"].as_double(), 4.0);
  EXPECT_TRUE(space["flag"].as_bool());
  EXPECT_EQ(space["kind"].as_string(), "bsplin");
  EXPECT_EQ(space["ints"].as_ints(), (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(root["problem"]["pde"].as_string(), "poisson");

  std::vector<ConfigNode> min = root["domain"]["min"].items();
  ASSERT_EQ(min.size(), 2u);
  EXPECT_EQ(min[1].path(), "domain.min[1]");
  EXPECT_EQ(root["domain"]["min"].as_doubles(), (std::vector<double>{0.0, 1.5}));

  EXPECT_TRUE(space.has("degree"));
  EXPECT_FALSE(space.has("nothere"));
  EXPECT_FALSE(space.find("nothere").has_value());
  ASSERT_TRUE(space.find("count").has_value());
  EXPECT_EQ(space.find("count")->as_int(), 4);
}

TEST(ConfigNode, GettersWithFallback) {
  ConfigNode space = ConfigNode::load_string(kQuick, "quick.yaml")["space"];
  EXPECT_EQ(space.get_int("count", 9), 4);
  EXPECT_EQ(space.get_int("missing", 9), 9);
  EXPECT_DOUBLE_EQ(space.get_double("levels", 1.0), 2.5);
  EXPECT_DOUBLE_EQ(space.get_double("missing", -1.25), -1.25);
  EXPECT_EQ(space.get_string("kind", "x"), "bsplin");
  EXPECT_EQ(space.get_string("missing", "x"), "x");
  EXPECT_TRUE(space.get_bool("flag", false));
  EXPECT_FALSE(space.get_bool("missing", false));
  // Present but wrong: the fallback does not hide the mistake.
  EXPECT_EQ(error_of([&] { space.get_int("degree", 2); }),
            "quick.yaml:9:11: space.degree: expected an integer, got 'three'");
}

TEST(ConfigNode, WrongTypesNameThePlace) {
  ConfigNode root = ConfigNode::load_string(kQuick, "quick.yaml");
  ConfigNode space = root["space"];
  EXPECT_EQ(error_of([&] { space["degree"].as_int(); }),
            "quick.yaml:9:11: space.degree: expected an integer, got 'three'");
  EXPECT_EQ(error_of([&] { space["levels"].as_int(); }),
            "quick.yaml:10:11: space.levels: expected an integer, got '2.5'");
  EXPECT_EQ(error_of([&] { space["degree"].as_double(); }),
            "quick.yaml:9:11: space.degree: expected a number, got 'three'");
  EXPECT_EQ(error_of([&] { space["kind"].as_bool(); }),
            "quick.yaml:8:9: space.kind: expected true or false, got 'bsplin'");
  EXPECT_EQ(error_of([&] { space.as_string(); }), "quick.yaml:7:3: space: expected a string, got a map");
  EXPECT_EQ(error_of([&] { space["count"].as_doubles(); }),
            "quick.yaml:11:10: space.count: expected a sequence of numbers, got '4'");
  // The bad element of a sequence is named by its index and located exactly.
  EXPECT_EQ(error_of([&] { root["domain"]["max"].as_doubles(); }),
            "quick.yaml:5:12: domain.max[1]: expected a number, got 'abc'");
  // An empty value is reported at its key, not at the next line.
  EXPECT_EQ(error_of([&] { space["empty"].as_int(); }),
            "quick.yaml:14:3: space.empty: expected an integer, got nothing");
  EXPECT_EQ(error_of([&] { space.fail("custom problem"); }), "quick.yaml:7:3: space: custom problem");
  EXPECT_EQ(space["count"].where(), "quick.yaml:11:10: space.count");
  EXPECT_EQ(root.where(), "quick.yaml:1:1");
}

TEST(ConfigNode, IntegerParsingIsStrict) {
  auto value = [](const std::string& text) { return ConfigNode::load_string("v: " + text)["v"]; };
  EXPECT_EQ(value("+12").as_int(), 12);
  EXPECT_EQ(value("0").as_int(), 0);
  EXPECT_THROW(value("2.5").as_int(), InputError);
  EXPECT_THROW(value("abc").as_int(), InputError);
  EXPECT_THROW(value("3x").as_int(), InputError);
  EXPECT_THROW(value("99999999999").as_int(), InputError);
  EXPECT_DOUBLE_EQ(value("1e-3").as_double(), 1e-3);
  EXPECT_DOUBLE_EQ(value("-.5").as_double(), -0.5);
  EXPECT_THROW(value("1.5.2").as_double(), InputError);
  EXPECT_THROW(value("nan").as_double(), InputError);
  EXPECT_FALSE(value("off").as_bool());
  EXPECT_TRUE(value("true").as_bool());
}

TEST(ConfigNode, UnknownKeySuggestsNearest) {
  ConfigNode root = ConfigNode::load_string(kQuick, "quick.yaml");
  const std::vector<std::string> allowed = {"degree", "kind", "levels", "count",
                                            "flag",   "ints", "empty",  "neg"};
  EXPECT_EQ(error_of([&] { root["space"].check_keys(allowed); }),
            "quick.yaml:7:3: unknown key 'degre' in 'space' (did you mean 'degree'?)");
  // Nothing close: list the valid keys instead.
  EXPECT_EQ(error_of([&] {
              root.check_keys({"problem", "domain"});
            }),
            "quick.yaml:6:1: unknown key 'space' at the top level (valid keys: 'problem', 'domain')");
  EXPECT_NO_THROW(root.check_keys({"problem", "domain", "space"}));
  EXPECT_EQ(error_of([] {
              ConfigNode::load_string("a: 1\nb: 2\na: 3\n", "d.yaml").check_keys({"a", "b"});
            }),
            "d.yaml:3:1: duplicate key 'a' at the top level");
}

TEST(ConfigNode, MissingKeyNamesParentMap) {
  ConfigNode root = ConfigNode::load_string(kQuick, "quick.yaml");
  EXPECT_EQ(error_of([&] { root["domain"]["type"]; }), "quick.yaml:4:3: missing key 'type' in 'domain'");
  EXPECT_EQ(error_of([&] { root["output"]; }), "quick.yaml:1:1: missing key 'output' at the top level");
  EXPECT_EQ(error_of([&] { root["space"]["count"]["x"]; }),
            "quick.yaml:11:10: space.count: expected a map with key 'x', got '4'");
}

TEST(ConfigNode, Choice) {
  ConfigNode space = ConfigNode::load_string(kQuick, "quick.yaml")["space"];
  EXPECT_EQ(error_of([&] {
              space["kind"].as_choice({"bspline", "nurbs", "hct"});
            }),
            "quick.yaml:8:9: space.kind: expected one of 'bspline', 'nurbs', 'hct', got 'bsplin' (did you "
            "mean 'bspline'?)");
  EXPECT_EQ(error_of([&] {
              space["kind"].as_choice({"argyris", "hct"});
            }),
            "quick.yaml:8:9: space.kind: expected one of 'argyris', 'hct', got 'bsplin'");
  EXPECT_EQ(ConfigNode::load_string("k: nurbs")["k"].as_choice({"bspline", "nurbs"}), "nurbs");
}

TEST(ConfigNode, NearestWord) {
  EXPECT_EQ(nearest_word("degre", {"degree", "levels"}), "degree");
  EXPECT_EQ(nearest_word("dgeree", {"degree", "levels"}), "degree");  // distance 2
  EXPECT_EQ(nearest_word("regularty", {"degree", "regularity"}), "regularity");
  EXPECT_EQ(nearest_word("zzz", {"degree", "levels"}), "");
  EXPECT_EQ(nearest_word("z", {"x", "y"}), "");  // a total rewrite is no suggestion
  // max(2, len/3): a 12-letter word tolerates 4 edits, not 5.
  EXPECT_EQ(nearest_word("abcdefghijkl", {"abcdefghXXXX"}), "abcdefghXXXX");
  EXPECT_EQ(nearest_word("abcdefghijkl", {"abcdefgXXXXX"}), "");
  EXPECT_EQ(nearest_word("anything", {}), "");
}

TEST(ConfigNode, SyntaxErrorHasLocation) {
  const std::string message = error_of([] { ConfigNode::load_string("a: 1\nb: [1, 2\nc: 3\n", "bad.yaml"); });
  EXPECT_EQ(message.rfind("bad.yaml:", 0), 0u) << message;
  EXPECT_NE(message.find("YAML syntax error"), std::string::npos) << message;
  EXPECT_EQ(error_of([] { ConfigNode::load_string("a: b: c\n", "bad.yaml"); }),
            "bad.yaml:1:5: YAML syntax error: illegal map value");
}

TEST(ConfigNode, Files) {
  EXPECT_EQ(error_of([] { ConfigNode::load_file("/nonexistent/missing.yaml"); }),
            "/nonexistent/missing.yaml: cannot open file");
  const auto path = std::filesystem::temp_directory_path() / "iga_config_node_test.yaml";
  {
    std::ofstream out(path);
    out << "space:\n  degree: 3\n  degre: 4\n";
  }
  ConfigNode root = ConfigNode::load_file(path.string());
  EXPECT_EQ(root.file(), path.string());
  EXPECT_EQ(root["space"]["degree"].as_int(), 3);
  EXPECT_EQ(error_of([&] { root["space"].check_keys({"degree"}); }),
            path.string() + ":3:3: unknown key 'degre' in 'space' (did you mean 'degree'?)");
  std::filesystem::remove(path);
}

TEST(ConfigNode, FilesThatAreNotConfigsAreRefusedBeforeReading) {
  // /dev/zero would otherwise be read until memory runs out.
  EXPECT_EQ(error_of([] { ConfigNode::load_file("/dev/zero"); }), "/dev/zero: not a regular file");
  const auto dir = std::filesystem::temp_directory_path();
  EXPECT_EQ(error_of([&] { ConfigNode::load_file(dir.string()); }), dir.string() + ": not a regular file");
  const auto path = dir / ("iga_config_node_test_big_" + std::to_string(::getpid()) + ".yaml");
  {
    std::ofstream out(path);
    out << "a: \"" << std::string(ConfigNode::kMaxConfigBytes, 'x') << "\"\n";
  }
  const std::string message = error_of([&] { ConfigNode::load_file(path.string()); });
  std::filesystem::remove(path);
  EXPECT_EQ(message.rfind(path.string() + ": file is ", 0), 0u) << message;
  EXPECT_NE(message.find("at most 1048576"), std::string::npos) << message;
}

TEST(ConfigNode, EmptyDocumentAndSection) {
  ConfigNode empty = ConfigNode::load_string("", "e.yaml");
  EXPECT_FALSE(empty.has("space"));
  EXPECT_TRUE(empty.keys().empty());
  EXPECT_EQ(error_of([&] { empty["space"]; }), "e.yaml: missing key 'space' at the top level");
  ConfigNode section = ConfigNode::load_string("out:\nother: 1\n", "s.yaml")["out"];
  EXPECT_NO_THROW(section.check_keys({"vtk"}));
  EXPECT_EQ(error_of([&] { section["vtk"]; }), "s.yaml:1:1: missing key 'vtk' in 'out'");
}

TEST(ConfigNode, RootIsReachableFromAnyNode) {
  // Builders handed one section (a domain) still read the config's limits: through root().
  const ConfigNode root = ConfigNode::load_string("a: {b: [{c: 1}]}\nlimits: {max_elements: 5}\n", "cfg.yaml");
  const ConfigNode deep = root["a"]["b"].items()[0]["c"];
  EXPECT_EQ(deep.root().path(), "");
  EXPECT_EQ(deep.root()["limits"]["max_elements"].as_int(), 5);
  EXPECT_EQ(deep.root()["limits"]["max_elements"].where(), root["limits"]["max_elements"].where());
}

}  // namespace
}  // namespace iga
