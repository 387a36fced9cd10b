// `shadowlab techniques` and `shadowlab info` (InfoCommands.h).
#include "InfoCommands.h"

#include <shadowlab/Context.h>
#include <shadowlab/Options.h>
#include <shadowlab/Scene.h>
#include <shadowlab/Techniques.h>

#include <iostream>
#include <string>

namespace shadowlab::tool {

int runTechniques(bool markdown) {
    if (markdown) {
        std::cout << techniquesMarkdown();
        return 0;
    }
    for (const TechniqueInfo& t : techniques()) {
        // A light whose scene names no technique gets the default one.
        std::cout << t.name << (t.name == ShadowSettings{}.technique ? " (the default)" : "") << ": " << t.summary << "\n";
        for (const OptionField& f : t.options->fields)
            std::cout << "  lights[i].shadow." << t.name << "." << f.key << " = " << t.options->defaultText(f) << "  ("
                      << OptionTable::rangeText(f) << (f.unit.empty() ? "" : " " + f.unit) << ") " << f.doc << "\n";
    }
    return 0;
}

int runInfo() {
    Context context = Context::createHeadless();
    const GlInfo& i = context.info();
    std::cout << "shadowlab " << SHADOWLAB_VERSION << "\n"
              << "platform:           " << i.platform << "\n"
              << "GL vendor:          " << i.vendor << "\n"
              << "GL renderer:        " << i.renderer << "\n"
              << "GL version:         " << i.version << "\n"
              << "GLSL version:       " << i.glslVersion << "\n"
              << "max texture size:   " << i.maxTextureSize << "\n"
              << "max cube map size:  " << i.maxCubeMapSize << "\n"
              << "max array layers:   " << i.maxArrayLayers << "\n"
              << "max viewport:       " << i.maxViewportWidth << "x" << i.maxViewportHeight << "\n"
              << "device memory free: "
              << (i.deviceMemoryBytes > 0 ? std::to_string(i.deviceMemoryBytes / 1048576) + " MiB (" + i.deviceMemorySource + ")"
                                          : std::string("not reported by the driver"))
              << "\n"
              << "build: viewer " << (SHADOWLAB_VIEWER ? "on" : "off")
#ifdef SHADOWLAB_WITH_EMBREE
              << ", embree reference on"
#else
              << ", embree reference off"
#endif
              << "\n";
    return 0;
}

} // namespace shadowlab::tool
