// The Python module's exact shadows (Module.h): a light's ray-traced
// visibility, and the scene against it as compare's metrics.json with its
// images as arrays.
#include "Module.h"

#include <shadowlab/Compare.h>
#include <shadowlab/Limits.h>

#include <algorithm>

namespace shadowlab::python {

namespace {

CompareOptions compareOptions(int width, int height, int softSamples, double time) {
    checkSoftSamples(softSamples, width, height);
    CompareOptions options;
    options.width = width;
    options.height = height;
    options.softSamples = softSamples;
    options.timeSeconds = time;
    return options;
}

} // namespace

// Light `light`'s exact visibility at the frame's surface points (Embree;
// 1 lit, 0 shadowed, 0 where the light does not reach: background, outside
// a cone or range, facing away), in compare's 16-bit steps. The light is
// traced alone: the others and its own technique do not run.
py::array_t<float> reference(const PyScene& s, int light, int width, int height, int softSamples, double time) {
    if (light < 0 || static_cast<std::size_t>(light) >= s.scene->lights.size())
        throw InputFailure("light " + std::to_string(light) + ": the scene has " + std::to_string(s.scene->lights.size()) + " light(s)");
    const CompareOptions options = compareOptions(width, height, softSamples, time);
    auto alone = std::make_shared<Scene>(*s.scene);
    alone->lights = {s.scene->lights[static_cast<std::size_t>(light)]};
    alone->lights[0].shadow.technique = "none";
    PyScene one = s;
    one.scene = alone;
    ImageGray16 truth;
    drawn(one, width, height, time, [&](Renderer& renderer, const Scene& at) {
        truth = std::move(compareWithReference(renderer, at, options).lights.at(0).referenceVisibility);
    });
    return unit(truth);
}

// compare's metrics.json as a dict (the library's comparisonMetricsJson,
// which the CLI writes), its image files as arrays instead: "images" (the
// frame's and the reference's) and each light's "images" (error,
// visibility and techniqueVisibility in 0..1, reach as a mask).
py::dict compare(const PyScene& s, int width, int height, int softSamples, double time) {
    const CompareOptions options = compareOptions(width, height, softSamples, time);
    try {
        checkSceneReferenceRays(width, height, softSamples,
                                static_cast<std::size_t>(std::count_if(s.scene->lights.begin(), s.scene->lights.end(), [](const Light& l) { return l.size > 0.0f; })));
    } catch (const Error& e) {
        raiseInput(e);
    }
    Comparison c;
    std::string metrics;
    drawn(s, width, height, time, [&](Renderer& renderer, const Scene& at) {
        c = compareWithReference(renderer, at, options);
        metrics = comparisonMetricsJson(at, s.text ? "<json>" : s.path, options, c, false);
    });
    py::dict out = py::module_::import("json").attr("loads")(metrics);
    py::list lights = out["lights"];
    for (std::size_t i = 0; i < c.lights.size(); ++i) {
        py::dict images;
        images["error"] = rgba(std::move(c.lights[i].errorImage));
        images["visibility"] = unit(c.lights[i].referenceVisibility);
        images["techniqueVisibility"] = unit(c.lights[i].techniqueVisibility);
        images["reach"] = mask(c.lights[i].reach);
        py::dict record = lights[i];
        record["images"] = images;
    }
    py::dict images;
    images["technique"] = rgba(std::move(c.technique));
    images["reference"] = rgba(std::move(c.reference));
    out["images"] = images;
    return out;
}

} // namespace shadowlab::python
