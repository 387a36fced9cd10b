// Renders the built-in default scene through the installed library, and
// catches a shadowlab::Error the library throws (its type information is
// exported, so a user's catch matches it across the shared library).
#include <shadowlab/Context.h>
#include <shadowlab/Error.h>
#include <shadowlab/Image.h>
#include <shadowlab/Renderer.h>
#include <shadowlab/SceneFile.h>

#include <iostream>
#include <string>

int main(int argc, char** argv) {
    if (argc != 2) return 2;
    try {
        (void)shadowlab::parseScene("{", "bad.json", ".");
        std::cerr << "parseScene accepted a broken scene\n";
        return 1;
    } catch (const shadowlab::Error& e) {
        if (std::string(e.what()).find("bad.json") == std::string::npos) {
            std::cerr << "unexpected message: " << e.what() << "\n";
            return 1;
        }
    }
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
