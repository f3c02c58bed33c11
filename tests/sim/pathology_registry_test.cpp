/// @file pathology_registry_test.cpp
/// @brief The pathology plug-ins' one list (sim/pathology/pathology_list.h): every spec a model parses is found by
///        its name, the help texts and the docs' table are the list's, and a model's flags (only from the start,
///        applied last, the breathing it asks for) are the ones the course and the runtime act on.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "sim/pathology/pathology.h"

using namespace lungar::sim;

namespace {

std::string docs_text(const std::string& name) {
  std::ifstream in(std::string(LUNGAR_SOURCE_DIR) + "/docs/" + name);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST(PathologyRegistry, EveryModelIsFoundByItsNameAndNamedInTheHelpList) {
  const std::string help = pathology_syntaxes();
  ASSERT_GE(pathology_models().size(), 4u);
  for (const PathologyModel* m : pathology_models()) {
    EXPECT_NE(help.find(std::string(m->syntax())), std::string::npos) << help;
    // A spec with the model's name and a wrong field is that model's error, naming the spec.
    const std::string name(m->name());
    auto refused = parse_pathology(name + ":no-such-field");
    ASSERT_FALSE(refused) << name;
    EXPECT_NE(refused.error().find("'" + name + ":no-such-field'"), std::string::npos) << refused.error();
  }
  EXPECT_NE(help.find("SIDE left or right"), std::string::npos) << help;
  EXPECT_EQ(help.find("SIDE left or right", help.find("SIDE left or right") + 1), std::string::npos)
      << "a field that several models take is said once: " << help;
  for (const char* spec :
       {"pneumothorax:right:30:tension", "consolidation:left:upper", "emphysema:0.5:left", "ards:0.6"}) {
    auto p = parse_pathology(spec);
    ASSERT_TRUE(p) << p.error();
    EXPECT_EQ(std::string(spec).rfind(std::string((*p)->model().name()) + ":", 0), 0u) << spec;
  }
}

TEST(PathologyRegistry, TheDocsTableIsTheRegistrys) {
  const std::string docs = docs_text("pathologies.md");
  EXPECT_NE(docs.find(pathology_table()), std::string::npos)
      << "docs/pathologies.md's table is not the registry's; it should read:\n"
      << pathology_table();
}

TEST(PathologyRegistry, OnlyArdsIsFromTheStartAndLastAndOnlyEmphysemaAsksForABreathing) {
  for (const PathologyModel* m : pathology_models()) {
    SCOPED_TRACE(std::string(m->name()));
    EXPECT_EQ(m->may_change_in_a_run(), m->name() != "ards");
    EXPECT_EQ(m->applied_last(), m->name() == "ards");
    EXPECT_EQ(m->breathing_preset(), m->name() == "emphysema" ? "emphysema" : "");
  }
}
