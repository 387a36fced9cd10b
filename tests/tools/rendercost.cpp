// rendercost SCENE WIDTH HEIGHT COUNT [--new-renderer]: renders SCENE COUNT
// times through the library in C++ as a program that draws one scene
// again and again would (one Renderer, the scene uploaded once; each call
// the scene at time 0, the frame, the pixels read back into an image the
// caller keeps until the next), and prints the median milliseconds a
// call, for scripts/python-cost.sh, which times the Python module's
// render() of the same scene beside it. --new-renderer: a Renderer made
// and the scene uploaded in every call too. Exit 0, or 2 on bad input.
#include <shadowlab/Context.h>
#include <shadowlab/Error.h>
#include <shadowlab/Renderer.h>
#include <shadowlab/SceneFile.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <vector>

int main(int argc, char** argv) {
    const bool fresh = argc == 6 && std::strcmp(argv[5], "--new-renderer") == 0;
    if (argc != 5 && !fresh) {
        std::fprintf(stderr, "usage: rendercost SCENE WIDTH HEIGHT COUNT [--new-renderer]\n");
        return 2;
    }
    try {
        using namespace shadowlab;
        const Scene scene = loadSceneFile(argv[1], {});
        const int width = std::atoi(argv[2]), height = std::atoi(argv[3]), count = std::atoi(argv[4]);
        if (width < 1 || height < 1 || count < 1) throw Error("WIDTH, HEIGHT and COUNT must be at least 1");
        Context context = Context::createHeadless();
        std::vector<double> ms;
        std::optional<Renderer> renderer;
        ImageRGBA8 image;
        for (int i = 0; i < count; ++i) {
            const auto start = std::chrono::steady_clock::now();
            const Scene at = sceneAtTime(scene, 0.0);
            if (fresh || !renderer) {
                renderer.reset();
                renderer.emplace(context);
                renderer->upload(scene);
            }
            RenderOptions options;
            options.width = width;
            options.height = height;
            renderer->render(at, options);
            image = renderer->readColor();
            ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        }
        std::sort(ms.begin(), ms.end());
        std::printf("%.3f\n", ms[ms.size() / 2]);
        return image.pixels.empty() ? 1 : 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "rendercost: %s\n", e.what());
        return 2;
    }
}
