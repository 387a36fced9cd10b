// A program linked with shadowlab_scene alone (the floors below OpenGL, no
// GL library): it reads each scene named on its command line, as the CLI
// would, and prints one line per light with its technique and that
// technique's summary, and the markdown of every technique's options. That
// it links at all shows the scene loader, the technique catalog and the
// options tables need no GL technique (docs/architecture.md, "Floors").
// Exit 1 with the loader's message on a scene that does not load, or when a
// light's technique is unknown to the catalog or refuses the light.
#include <shadowlab/Error.h>
#include <shadowlab/SceneFile.h>
#include <shadowlab/Techniques.h>

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
    using namespace shadowlab;
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s SCENE.json...\n", argv[0]);
        return 2;
    }
    for (int a = 1; a < argc; ++a) {
        try {
            const Scene scene = loadSceneFile(argv[a]);
            for (std::size_t i = 0; i < scene.lights.size(); ++i) {
                const Light& light = scene.lights[i];
                const TechniqueInfo* info = findTechnique(light.shadow.technique);
                const std::string reason = unsupportedReason(light.shadow.technique, light);
                if (!info || !reason.empty()) {
                    std::fprintf(stderr, "%s: lights[%zu]: %s\n", argv[a], i, info ? reason.c_str() : "unknown technique");
                    return 1;
                }
                std::printf("%s: lights[%zu] %s: %s\n", argv[a], i, info->name.c_str(), info->summary.c_str());
            }
        } catch (const Error& e) {
            std::fprintf(stderr, "%s\n", e.what());
            return 1;
        }
    }
    std::printf("%zu techniques, %zu characters of options reference\n", techniques().size(), techniquesMarkdown().size());
    return 0;
}
