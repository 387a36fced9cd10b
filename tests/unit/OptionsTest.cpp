// Options tables: one table per technique drives the parser (errors with the
// JSON path), --set, the generated docs; the doc must match the tables.
#include "ErrorText.h"

#include <shadowlab/Error.h>
#include <shadowlab/MapOptions.h>
#include <shadowlab/Options.h>
#include <shadowlab/SceneFile.h>
#include <shadowlab/Techniques.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace shadowlab;

namespace {

enum class Flavour { Plain, Fancy };

struct Sample {
    static constexpr const char* kTechnique = "sample";
    int size = 256;
    float radius = 1.5f;
    bool enabled = true;
    Flavour flavour = Flavour::Fancy;
};

OptionTable sampleTable() {
    return OptionTableFor<Sample>("sample")
        .integer(&Sample::size, "size", 16, 4096, "texels", "side of the map")
        .number(&Sample::radius, "radius", 0.0, 10.0, "scene units", "filter radius")
        .boolean(&Sample::enabled, "enabled", "on or off")
        .choice(&Sample::flavour, "flavour", {"plain", "fancy"}, "how it looks")
        .build();
}

} // namespace

TEST(OptionTable, DefaultsRangesAndValuesAreReadFromTheStruct) {
    const OptionTable t = sampleTable();
    ASSERT_EQ(t.fields.size(), 4u);
    EXPECT_EQ(t.defaultText(*t.find("size")), "256");
    EXPECT_EQ(t.defaultText(*t.find("radius")), "1.5");
    EXPECT_EQ(t.defaultText(*t.find("enabled")), "true");
    EXPECT_EQ(t.defaultText(*t.find("flavour")), "\"fancy\"");
    EXPECT_EQ(OptionTable::rangeText(*t.find("size")), "16..4096");
    EXPECT_EQ(OptionTable::rangeText(*t.find("flavour")), "\"plain\", \"fancy\"");
    EXPECT_EQ(t.find("nope"), nullptr);
    std::any options = t.makeDefault();
    t.find("size")->set(options, 1024);
    t.find("flavour")->set(options, 0);
    t.find("enabled")->set(options, 0);
    EXPECT_EQ(std::any_cast<Sample&>(options).size, 1024);
    EXPECT_EQ(std::any_cast<Sample&>(options).flavour, Flavour::Plain);
    EXPECT_FALSE(std::any_cast<Sample&>(options).enabled);
    EXPECT_EQ(t.valueText(*t.find("flavour"), options), "\"plain\"");
}

TEST(OptionTable, MarkdownHasOneRowPerField) {
    const std::string md = sampleTable().markdown();
    EXPECT_NE(md.find("| `size` | integer | `256` | 16..4096 | texels | side of the map |\n"), std::string::npos) << md;
    EXPECT_NE(md.find("| `flavour` | string | `\"fancy\"` | \"plain\", \"fancy\" | - | how it looks |\n"), std::string::npos) << md;
}

TEST(ShadowSettings, GetReturnsTheBlockOrTheDefaults) {
    ShadowSettings s;
    EXPECT_EQ(s.get<Sample>().size, 256);  // no block: defaults
    s.edit<Sample>().size = 64;
    EXPECT_EQ(s.get<Sample>().size, 64);
    EXPECT_EQ(s.options.count("sample"), 1u);
}

TEST(SceneFileShadow, TechniqueNamesComeFromTheRegistry) {
    std::string names;
    for (const TechniqueInfo& t : techniques()) names += (names.empty() ? "" : ", ") + t.name;
    EXPECT_EQ(errorOf([] { parseScene(R"({"lights": [{"type": "spot", "position": [0, 1, 0], "shadow": {"technique": "mapp"}}]})", "s.json", "."); }),
              "s.json: lights[0].shadow.technique: unknown technique 'mapp' (expected one of: " + names + ")");
    EXPECT_EQ(errorOf([] { parseScene(R"({"lights": [{"type": "directional", "shadow": {"mapp": {}}}]})", "s.json", "."); }),
              "s.json: lights[0].shadow.mapp: unknown key (expected one of: technique, " + names + ")");
    EXPECT_EQ(errorOf([] { parseScene(R"({"lights": [{"type": "directional", "shadow": {"none": {"size": 1}}}]})", "s.json", "."); }),
              "s.json: lights[0].shadow.none.size: unknown key (technique 'none' has no options)");
    EXPECT_EQ(errorOf([] { parseScene(R"({"lights": [{"type": "directional"}]})", "s.json", ".", {"lights[0].shadow.technique=mapp"}); }),
              "--set lights[0].shadow.technique=mapp: lights[0].shadow.technique: unknown technique 'mapp' (expected one of: " + names + ")");
}

// Bench's baseline comes from the technique's registry entry: a map light's
// is the plainest map of the same size (one 2D map, depth, the hardware
// filter), worth timing against where the light has cascades, another
// filter or another representation; a technique without the hook is its
// own baseline.
TEST(TechniqueBaseline, AMapsIsThePlainestMapOfTheSameSize) {
    const Scene scene = parseScene(R"({"lights": [
        {"type": "directional", "shadow": {"technique": "map", "map": {"size": 512, "filter": "pcss", "cascades": 3}}},
        {"type": "directional", "shadow": {"technique": "map", "map": {"size": 256, "format": "r8"}}},
        {"type": "directional", "shadow": {"technique": "none"}}]})", "s.json", ".");
    const ShadowBaseline soft = shadowBaseline(scene.lights[0]);
    EXPECT_TRUE(soft.differs);
    EXPECT_EQ(soft.shadow.technique, "map");
    const MapOptions& plainest = soft.shadow.get<MapOptions>();
    EXPECT_EQ(plainest.size, 512);
    EXPECT_EQ(plainest.cascades, 1);
    EXPECT_EQ(plainest.filter, MapFilter::Hardware);
    EXPECT_EQ(plainest.representation, MapRepresentation::Depth);
    // A format is not a variant timed against the baseline, but the
    // baseline is the plainest map still (when another light is timed).
    const ShadowBaseline r8 = shadowBaseline(scene.lights[1]);
    EXPECT_FALSE(r8.differs);
    EXPECT_EQ(r8.shadow.get<MapOptions>().size, 256);
    EXPECT_EQ(r8.shadow.get<MapOptions>().format, MapFormat::Depth32F);
    const ShadowBaseline none = shadowBaseline(scene.lights[2]);
    EXPECT_FALSE(none.differs);
    EXPECT_EQ(none.shadow.technique, "none");
}

TEST(SceneFormatDoc, CarriesExactlyTheGeneratedTechniqueTables) {
    std::ifstream in(std::filesystem::path(SHADOWLAB_SOURCE_DIR) / "docs" / "scene-format.md");
    ASSERT_TRUE(in) << "docs/scene-format.md";
    std::stringstream text;
    text << in.rdbuf();
    const std::string doc = text.str();
    const std::string begin = "<!-- BEGIN generated: shadowlab techniques --markdown -->\n", end = "<!-- END generated -->";
    const auto a = doc.find(begin), b = doc.find(end);
    ASSERT_NE(a, std::string::npos);
    ASSERT_NE(b, std::string::npos);
    EXPECT_EQ(doc.substr(a + begin.size(), b - a - begin.size()), techniquesMarkdown())
        << "docs/scene-format.md disagrees with the options tables: paste `shadowlab techniques --markdown` between its markers";
}

// Every number option of every technique takes the ends of its own range,
// as written in the docs (0.1 parsed to a float is a hair above the double
// 0.1: the check compares in the member's own type).
TEST(OptionsTest, EveryNumberOptionTakesTheEndsOfItsRange) {
    for (const shadowlab::TechniqueInfo& t : shadowlab::techniques()) {
        if (!t.options) continue;
        for (const shadowlab::OptionField& f : t.options->fields) {
            if (f.kind != shadowlab::OptionKind::Number) continue;
            for (double end : {f.minimum, f.maximum}) {
                std::ostringstream value;
                value << end;
                const std::string set = "lights[0].shadow." + t.name + "." + f.key + "=" + value.str();
                EXPECT_NO_THROW(shadowlab::defaultScene({set})) << set;
            }
        }
    }
}

// The lectures' name for percentage-closer filtering: `filter: pcf` is the
// grid filter with the lecture's 8x8 kernel (64 taps), a kernel the block
// writes kept; the allowed values say so, and a name that is neither a
// filter nor an alias is still refused.
TEST(OptionAlias, PcfIsTheGridFilterWithTheLecturesKernel) {
    const auto mapOf = [](const std::string& block) {
        const Scene s = parseScene(R"({"lights": [{"type": "directional", "shadow": {"technique": "map", "map": )" + block + "}}]}", "s.json", ".");
        return s.lights[0].shadow.get<MapOptions>();
    };
    const MapOptions pcf = mapOf(R"({"filter": "pcf"})");
    EXPECT_EQ(pcf.filter, MapFilter::Grid);
    EXPECT_EQ(pcf.kernel, 8);
    const MapOptions pcf3 = mapOf(R"({"filter": "pcf", "kernel": 3})");
    EXPECT_EQ(pcf3.filter, MapFilter::Grid);
    EXPECT_EQ(pcf3.kernel, 3);
    EXPECT_EQ(mapOf(R"({"filter": "grid"})").kernel, MapOptions{}.kernel);  // the grid's own default is untouched
    // On a point light's cube the lectures' 64 taps are a 4x4x4 grid.
    const Scene point = parseScene(R"({"lights": [{"type": "point", "position": [0, 2, 0], "shadow": {"map": {"filter": "pcf"}}}]})", "s.json", ".");
    EXPECT_EQ(point.lights[0].shadow.get<MapOptions>().kernel, 4);
    const Scene point8 = parseScene(R"({"lights": [{"type": "point", "position": [0, 2, 0], "shadow": {"map": {"filter": "pcf", "kernel": 8}}}]})", "s.json", ".");
    EXPECT_EQ(point8.lights[0].shadow.get<MapOptions>().kernel, 8);
    const std::string refused = errorOf([&] { mapOf(R"({"filter": "pcff"})"); });
    EXPECT_NE(refused.find("\"pcf\" (the lectures' PCF: grid with 64 taps"), std::string::npos) << refused;
}

// Each technique's page under docs/techniques/ carries its section of the
// generated tables between `<!-- options:NAME begin -->` and `end`, the
// same text `shadowlab techniques --markdown` prints for it (from its
// "#### `lights[i].shadow.NAME`" line to the table's last line), so an
// option is documented once, in its table (scripts/generated-docs.py
// pastes them).
TEST(TechniquePagesDoc, CarryTheirGeneratedOptionsTables) {
    const std::string all = techniquesMarkdown();
    const std::filesystem::path dir = std::filesystem::path(SHADOWLAB_SOURCE_DIR) / "docs" / "techniques";
    std::string pages;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        std::ifstream in(entry.path());
        std::stringstream text;
        text << in.rdbuf();
        pages += text.str();
    }
    for (const TechniqueInfo& t : techniques()) {
        SCOPED_TRACE(t.name);
        const std::string heading = "#### `lights[i].shadow." + t.name + "`\n";
        const auto from = all.find(heading);
        ASSERT_NE(from, std::string::npos);
        auto to = all.find("\n\n####", from);
        to = to == std::string::npos ? all.size() : to + 1;
        const std::string section = all.substr(from, to - from);
        const std::string begin = "<!-- options:" + t.name + " begin -->\n", end = "<!-- options:" + t.name + " end -->";
        const auto a = pages.find(begin);
        ASSERT_NE(a, std::string::npos) << "no page under docs/techniques/ holds " << begin;
        const auto b = pages.find(end, a);
        ASSERT_NE(b, std::string::npos);
        EXPECT_EQ(pages.substr(a + begin.size(), b - a - begin.size()), section)
            << "docs/techniques/: the " << t.name << " block disagrees with the options tables: run /usr/bin/python3 scripts/generated-docs.py";
    }
}
