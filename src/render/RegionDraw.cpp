// The base pass with its light's test only where the light's shadows can
// fall (RenderOptions::shadowRegions; Technique::shadowedPixels gives the
// rectangles). Each item, in drawShaded's order (nearest first), is drawn
// one of three ways:
//   - lit, without the test, where it does not receive shadows (its hook
//     returns 1 whatever the test finds) or its screen rectangle meets none
//     of the region's (the test would find it lit everywhere);
//   - with the test, whole, where the region covers nearly all of it or it has
//     many triangles (drawing it more than once would cost more vertices
//     than the skipped tests save);
//   - split: with the test inside each of the region's rectangles it meets
//     (a scissor each), then lit over the whole of it, whose fragments
//     where the first draws put this item fail the depth test (LESS, the
//     same depth) before they are shaded.
// Without rectangles, or where they cover more than nine tenths of the
// frame, every item that receives shadows is drawn with the test, whole.
// The image is the one drawShaded makes: every pixel takes its colour from
// the same item's fragment (the items still arrive in the same order at
// every pixel, so ties in depth go the same way) with visibility 1 outside
// the region either way.
#include "render/RendererImpl.h"

namespace shadowlab {

namespace {

// Above this many triangles an item meeting the region is drawn once, with
// the test: llvmpipe's vertex stage and set-up cost per triangle and draw
// (the bunny, 70k triangles, drawn in three rectangles and lit cost 30 ms
// more a frame than the tests it skipped).
constexpr std::size_t kSplitTriangles = 4096;
// A share of its screen rectangle in the region above which an item is
// drawn once, with the test (penumbra-step's ground, 0.59 in the region,
// split: its pcss lookup 15.6 -> 11.0 ms).
constexpr double kWholeShare = 0.9;
// A share of the frame in the region above which every item is (what the
// lit draws would skip is less than what the extra draws cost).
constexpr double kMostShare = 0.9;

enum class Way { Lit, Tested, Split };

} // namespace

void Renderer::Impl::drawShadedByRegion(const ShaderVariant& variant, const gl::RenderState& state, const std::vector<PixelRect>* region) {
    ShaderVariant lit = variant;  // the light's shading with visibility 1 (technique "none")
    const ShaderVariant plain;
    lit.techniqueFile = plain.techniqueFile;
    lit.techniqueVertexFile = plain.techniqueVertexFile;
    lit.techniqueDefines = plain.techniqueDefines;
    lit.techniqueIncludes = plain.techniqueIncludes;
    const glm::ivec2 size = targets->size;
    if (region) {
        double share = 0.0;
        for (const PixelRect& r : *region) share += area(r) / (double(size.x) * double(size.y));
        if (share > kMostShare)
            region = nullptr;  // hardly anything left to skip: every receiver with the test
        else
            count("shadowedShare", share);
    }

    // Each item's way, then runs of consecutive items of the same way, in order.
    std::vector<Way> ways(opaqueOrder.size());
    std::vector<PixelRect> rects(opaqueOrder.size());
    for (std::size_t k = 0; k < opaqueOrder.size(); ++k) {
        const std::size_t i = opaqueOrder[k];
        if (!items[i].receivesShadows) {
            ways[k] = Way::Lit;  // its hook returns 1 whatever the test says
            continue;
        }
        if (!region) {
            ways[k] = Way::Tested;
            continue;
        }
        rects[k] = screenRectOf(itemBounds[i], info->clipFromWorld, size);
        double inside = 0.0;
        for (const PixelRect& r : *region) inside += area(intersection(rects[k], r));
        const std::size_t triangles = scene->meshes[static_cast<std::size_t>(items[i].mesh)].triangleCount();
        ways[k] = inside <= 0.0                                                                   ? Way::Lit
                  : inside >= kWholeShare * area(rects[k]) || triangles > kSplitTriangles ? Way::Tested
                                                                                          : Way::Split;
    }
    // `state` is in effect on entry (the base pass applied it); only the
    // split draws' scissors change it, and it is applied again after them.
    std::vector<std::size_t> run;
    for (std::size_t k = 0; k < opaqueOrder.size();) {
        const Way way = ways[k];
        std::size_t end = k;
        run.clear();
        for (; end < opaqueOrder.size() && ways[end] == way; ++end) run.push_back(opaqueOrder[end]);
        if (way != Way::Split) {
            drawShaded(way == Way::Lit ? lit : variant, &run);
        } else {
            // Rectangle by rectangle, the run's items that meet it (each
            // pixel still sees the run's items in order), then the run lit.
            std::vector<std::size_t> in;
            for (const PixelRect& r : *region) {
                in.clear();
                for (std::size_t j = k; j < end; ++j)
                    if (overlaps(rects[j], r)) in.push_back(opaqueOrder[j]);
                if (in.empty()) continue;
                gl::RenderState cut = state;
                cut.scissor = std::array<GLint, 4>{r.x, r.y, r.z - r.x, r.w - r.y};
                gl::apply(cut);
                drawShaded(variant, &in);
            }
            gl::apply(state);
            drawShaded(lit, &run);
        }
        k = end;
    }
}

} // namespace shadowlab
