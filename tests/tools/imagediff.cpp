// imagediff A.png B.png [--from-x X]: prints how many pixels differ between
// two images of the same size (only columns x >= X when given), for the
// viewer's test (a screenshot against `shadowlab render` outside its panel).
// Exit 0 when it could compare, 2 on bad input.
#include <shadowlab/Error.h>
#include <shadowlab/Image.h>

#include <cstdlib>
#include <cstring>
#include <iostream>

int main(int argc, char** argv) {
    if (argc != 3 && !(argc == 5 && std::strcmp(argv[3], "--from-x") == 0)) {
        std::cerr << "usage: imagediff A.png B.png [--from-x X]\n";
        return 2;
    }
    try {
        const shadowlab::ImageRGBA8 a = shadowlab::readPng(argv[1]), b = shadowlab::readPng(argv[2]);
        if (a.width != b.width || a.height != b.height) {
            std::cerr << "imagediff: " << a.width << "x" << a.height << " against " << b.width << "x" << b.height << "\n";
            return 2;
        }
        const int from = argc == 5 ? std::atoi(argv[4]) : 0;
        std::size_t differ = 0;
        for (int y = 0; y < a.height; ++y)
            for (int x = from; x < a.width; ++x) {
                const std::size_t i = (static_cast<std::size_t>(y) * a.width + x) * 4;
                differ += std::memcmp(&a.pixels[i], &b.pixels[i], 3) != 0;
            }
        std::cout << differ << "\n";
        return 0;
    } catch (const shadowlab::Error& e) {
        std::cerr << "imagediff: " << e.what() << "\n";
        return 2;
    }
}
