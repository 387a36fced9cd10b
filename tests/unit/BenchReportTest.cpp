// The bench report (report.html, src/bench/Report.cpp) from a results.json
// as bench writes it: no GL needed.
#include <shadowlab/Bench.h>
#include <shadowlab/Image.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include <unistd.h>

namespace fs = std::filesystem;

namespace {

// One row of `shadowlab bench scenes/torus-floating.json --frames 1 --warmup 0
// --width 64 --height 36` (its lookup floor clocked at -3.2 ms: two
// differences of passes clocked apart on a busy machine).
const char* kResults = R"json(
{"flips":false,"fps":30.0,"frames":1,"glVersion":"4.5 (Core Profile) Mesa 22.3.6","height":36,"overrides":[],
"renderer":"llvmpipe (LLVM 15.0.6, 256 bits)","results":[{"baseLight":0,"cachedFrameMs":{"max":0.720435,
"median":0.720435,"min":0.720435},"clock":"cpu-finish","floorFrameMs":15.329956000373542,"floorFrameOverUnshadowed":2.389418694749178,
"frameMs":{"max":28.369347,"median":28.369347,"min":28.369347},"frameOverHardMap":1.0,"frameOverUnshadowed":4.421816219040339,
"frames":1,"lights":[{"coloured":false,"edgePixels":85,"errorImage":"images/0-torus-floating-error-0.png",
"falseLit":0.0,"falseLitAwayFromEdges":0.0,"falseShadow":0.0,"falseShadowAwayFromEdges":0.0,"leakedInUmbra":0.0,
"lookupFloorMs":-3.185192000120878,"lookupMs":0.28920499980449677,"meanAbsError":0.0,"name":"sun","penumbraRatio":0.0,
"receiverPixels":1390,"referencePenumbraPixels":0,"referenceShadowedPixels":29,"rmse":0.0,"rmseRgb":[0.0,
0.0,0.0],"shadowCounters":{"mapBytes":4194304.0},"shadowFloorMs":8.914188000373542,"shadowPassMs":5.353949998971075,
"shadowPassOverFloor":0.600609948853078,"shadowTriangles":4096.0,"soft":false,"technique":"map","techniquePenumbraPixels":0,
"texelFootprintMax":0.2326003760099411,"texelFootprintP50":0.019720908254384995,"texelFootprintP95":0.07449774444103241,
"type":"directional","umbraPixels":0}],"notes":[],"passMs":{"base":{"max":1.3730339999310672,"median":1.3730339999310672,
"min":1.3730339999310672},"shadow[0]":{"max":22.882506999652833,"median":22.882506999652833,"min":22.882506999652833},
"shadow[0].floor":{"max":8.914188000373542,"median":8.914188000373542,"min":8.914188000373542},"shadow[0].lookupFloor":{"max":8.614369000308216,
"median":8.614369000308216,"min":8.614369000308216},"shadow[0].lookupFloor.bare":{"max":5.88384100003168,
"median":5.88384100003168,"min":5.88384100003168},"shadow[0].lookupFloor.fetch":{"max":2.6986489999108016,
"median":2.6986489999108016,"min":2.6986489999108016}},"passTotalMs":{"max":24.2555409995839,"median":24.2555409995839,
"min":24.2555409995839},"referenceImage":"images/0-torus-floating-reference.png","referenceMs":6.159544,
"scene":"torus-floating","sceneFile":"scenes/torus-floating.json","settings":{},"techniqueImage":"images/0-torus-floating-technique.png",
"triangles":4098,"unshadowedFrameMs":{"max":6.415768,"median":6.415768,"min":6.415768}}],"rounds":1,
"softSamples":256,"time":0.0,"tool":"shadowlab bench","vary":[],"warmup":0,"width":64}
)json";

std::string reportOf(const nlohmann::json& results) {
    const fs::path dir = fs::temp_directory_path() / ("shadowlab-report-test-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "images");
    // The images the rows name (the report embeds them): any picture will do.
    shadowlab::ImageRGBA8 picture;
    picture.width = 2;
    picture.height = 2;
    picture.pixels.assign(16, 255);
    for (const char* name : {"0-torus-floating-technique.png", "0-torus-floating-reference.png", "0-torus-floating-error-0.png"})
        shadowlab::writePng(dir / "images" / name, picture);
    shadowlab::writeBenchReport(results.dump(), dir);
    std::ifstream in(dir / "report.html");
    std::stringstream text;
    text << in.rdbuf();
    fs::remove_all(dir);
    return text.str();
}

} // namespace

// Each row's stacked bar of where its time goes takes its parts' widths
// from differences of passes clocked apart (docs/metrics.md); on a busy
// machine the shadow pass above its floor and the lookup floor can come out
// below 0. A part below 0 is drawn as 0 wide, never as a negative width
// (which a browser ignores and the report's test could not read).
TEST(BenchReport, CostBarPartsAreNeverNegative) {
    nlohmann::json results = nlohmann::json::parse(kResults);
    nlohmann::json& light = results["results"][0]["lights"][0];
    for (const double pass : {-1.5, 0.0, 5.35}) {
        SCOPED_TRACE("shadowPassMs " + std::to_string(pass));
        light["shadowPassMs"] = pass;
        const std::string html = reportOf(results);
        const std::regex part(R"re(class="c-(floor|pass|lfloor|lookup|rest)" style="width:([^p]*)px")re");
        int parts = 0;
        for (auto it = std::sregex_iterator(html.begin(), html.end(), part); it != std::sregex_iterator(); ++it, ++parts)
            EXPECT_GE(std::stod((*it)[2].str()), 0.0) << (*it)[0].str();
        EXPECT_EQ(parts, 5);  // one bar: its five parts
    }
}
