// Renders the built-in default scene through the installed library.
#include <shadowlab/Context.h>
#include <shadowlab/Error.h>
#include <shadowlab/Image.h>
#include <shadowlab/Renderer.h>
#include <shadowlab/SceneFile.h>

#include <iostream>

int main(int argc, char** argv) {
    if (argc != 2) return 2;
    try {
        shadowlab::Context context = shadowlab::Context::createHeadless();
        shadowlab::Renderer renderer(context);
        const shadowlab::Scene scene = shadowlab::defaultScene();
        renderer.upload(scene);
        renderer.render(scene, {64, 36});
        shadowlab::writePng(argv[1], renderer.readColor());
    } catch (const shadowlab::Error& e) {
        std::cerr << e.what() << "\n";
        return 1;
    }
    return 0;
}
