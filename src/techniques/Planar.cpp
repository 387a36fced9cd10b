// Technique "planar": projected planar shadows (Wolberg's lecture, "Projective
// Shadows"). No shadow pass: in the light's own pass, per receiver plane,
// the receiver's visible pixels are marked in the stencil (1), every caster
// is drawn flattened onto the plane by the plane projection matrix where the
// mark is (1 -> 2: each pixel once, however many casters overlap, and never
// off the receiver's own pixels, so a finite floor clips its shadow), the
// remaining marks are cleared, and the light is added where the stencil is
// not 2. The flattened casters need no depth test (the stencil says where
// the receiver is visible), so they cannot z-fight with it. Style "lecture"
// draws them dark over the lit scene with depth only instead (Wolberg's look).
#include "techniques/Planar.h"

#include "geometry/LightCamera.h"
#include "techniques/NodeNames.h"
#include "techniques/Stencil.h"
#include "techniques/TechniqueBlock.h"

#include <shadowlab/Error.h>
#include <shadowlab/PlanarOptions.h>

#include "gl/Calls.h"
#include "shadow_planar_shared.h"

#include <algorithm>
#include <map>
#include <span>

namespace shadowlab {

namespace {

// The plane projection matrix (Wolberg's lecture): M = (n.L) I - L n^T maps a
// point v to where the ray from the light through v meets the plane n
// (homogeneous: w = (n.L) v.w - (n.v) L.w). L: the light's position with
// w = 1, or the direction towards a directional light with w = 0.
glm::mat4 planeProjection(const glm::vec4& n, const glm::vec4& L) {
    const float nL = glm::dot(n, L);
    glm::mat4 m(nL);  // nL on the diagonal
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) m[c][r] -= L[r] * n[c];
    return m;
}

struct Receiver {
    std::size_t item = 0;
    glm::vec4 plane{0.0f};  ///< oriented so that the light is on its positive side
    glm::mat4 projection{1.0f};
};

class PlanarShadow final : public Technique {
public:

    bool sharesBasePass(const Light&) const override { return false; }  // the light goes after the stencil

    void prepare(TechniqueHost& host, const FrameInfo& frame, std::span<const int> lights) override {
        receivers_.clear();
        for (int index : lights) {
            const Light& light = frame.scene.lights[static_cast<std::size_t>(index)];
            const PlanarOptions& o = light.shadow.get<PlanarOptions>();
            const std::string at = "lights[" + std::to_string(index) + "].shadow.planar.receivers";
            // Which items are receiver planes: named nodes, or every planar receiving item.
            const std::vector<std::size_t> chosen = itemsNamed(
                frame, o.receivers, at, [&](std::size_t i) { return frame.itemPlanes[i].has_value(); },
                "is not planar (its mesh's vertices are not in one plane)", [&](std::size_t i) { return frame.items[i].receivesShadows; });
            const glm::vec4 L = towardsLight(light);
            std::vector<Receiver>& list = receivers_[index];
            for (std::size_t i : chosen) {
                glm::vec4 n = *frame.itemPlanes[i];
                const float side = glm::dot(n, L);
                if (side == 0.0f) continue;  // the light in the plane: it lights nothing there
                if (side < 0.0f) n = -n;
                list.push_back({i, n, planeProjection(n, L)});
            }
            if (list.empty())
                host.note("lights[" + std::to_string(index) + "].shadow.planar: no planar receiver facing the light" +
                          (o.receivers.empty() ? " (no receiving node's mesh lies in one plane)" : "") + ", so this light casts no shadow");
        }
    }

    void renderLightPass(TechniqueHost& host, const FrameInfo& frame, const LightView& view) override {
        const PlanarOptions& o = view.light.shadow.get<PlanarOptions>();
        const std::vector<Receiver>& receivers = receivers_[view.index];
        const bool geometry = o.projection == PlanarProjection::Geometry;
        const gl::Program& mark = host.program({{{GL_VERTEX_SHADER, "scene.vert"}, {GL_FRAGMENT_SHADER, "shadow_planar_project.frag"}},
                                                "#define PLANAR_DARK 0\n"});
        auto projector = [&](bool dark) -> const gl::Program& {
            const std::string defines = std::string("#define PLANAR_DARK ") + (dark ? "1" : "0") + "\n#define PLANAR_GEOMETRY " + (geometry ? "1" : "0") + "\n";
            if (geometry)
                return host.program({{{GL_VERTEX_SHADER, "shadow_planar_project.vert"},
                                      {GL_GEOMETRY_SHADER, "shadow_planar_project.geom"},
                                      {GL_FRAGMENT_SHADER, "shadow_planar_project.frag"}},
                                     defines});
            return host.program({{{GL_VERTEX_SHADER, "shadow_planar_project.vert"}, {GL_FRAGMENT_SHADER, "shadow_planar_project.frag"}}, defines});
        };

        if (o.style == PlanarStyle::Lecture) {
            // Wolberg's look: the light everywhere, then the flattened casters
            // dark on top, depth-tested against the receivers they lie in.
            host.drawLit(host.litState());
            gl::RenderState dark;
            dark.depthFunc = GL_LEQUAL;
            dark.depthWrite = false;
            dark.blend = true;
            dark.blendSrc = GL_ZERO;
            dark.blendDst = GL_SRC_COLOR;  // colour x (1 - darkness), once per polygon
            dark.clipDistances = 2;        // drawProjected's casters, kept on the light's side of their planes
            host.apply(dark);
            const gl::Program& program = projector(true);
            if (geometry) {
                for (std::size_t first = 0; first < receivers.size(); first += SL_PLANAR_MAX_PLANES)
                    drawProjected(host, frame, o, geometry, program, std::span(receivers).subspan(first, std::min<std::size_t>(SL_PLANAR_MAX_PLANES, receivers.size() - first)));
            } else {
                for (std::size_t r = 0; r < receivers.size(); ++r) drawProjected(host, frame, o, geometry, program, std::span(receivers).subspan(r, 1));
            }
            return;
        }

        clearStencil(host);
        const gl::Program& program = projector(false);
        for (std::size_t r = 0; r < receivers.size(); ++r) {
            // 1: the receiver's visible pixels.
            gl::RenderState s;
            s.depthFunc = GL_EQUAL;  // the base pass's surfaces (scene.vert is invariant)
            s.depthWrite = false;
            s.noColor();
            s.stencil({GL_ALWAYS, 1, 0xFF, 0xFF, GL_KEEP, GL_KEEP, GL_REPLACE});
            host.apply(s);
            host.drawItems(ItemFilter::Opaque, mark, [&](std::size_t i) { return i == receivers[r].item; });
            // 1 -> 2 under the flattened casters: each pixel once, on the receiver only.
            gl::RenderState p;
            p.depthTest = false;
            p.depthWrite = false;
            p.noColor();
            p.stencil({GL_EQUAL, 1, 0xFF, 0xFF, GL_KEEP, GL_KEEP, GL_INCR});
            p.clipDistances = 2;  // drawProjected's casters, kept on the light's side of their planes
            host.apply(p);
            drawProjected(host, frame, o, geometry, program, std::span(receivers).subspan(r, 1));
            // The receiver's unshadowed pixels back to 0, so the next plane's casters cannot mark them.
            s.stencil({GL_EQUAL, 1, 0xFF, 0xFF, GL_KEEP, GL_KEEP, GL_ZERO});
            host.apply(s);
            host.drawItems(ItemFilter::Opaque, mark, [&](std::size_t i) { return i == receivers[r].item; });
        }
        gl::RenderState lit = host.litState();
        lit.stencil({GL_NOTEQUAL, 2, 0xFF, 0x00});
        host.drawLit(lit);
        clearStencil(host);  // as the next light expects it
    }

private:
    // Casters drawn flattened onto `planes` (receivers_ entries) by `program`
    // (its geometry-shader variant when `geometry`), skipping the receiver
    // itself and casters entirely behind every plane; the caller's state
    // has clip distances 0 and 1 on (the two sides the vertex stage writes).
    void drawProjected(TechniqueHost& host, const FrameInfo& frame, const PlanarOptions& o, bool geometry, const gl::Program& program,
                       std::span<const Receiver> planes) {
        shared::PlanarUniforms u{};
        for (std::size_t p = 0; p < planes.size(); ++p) {
            u.shadowFromWorld[p] = planes[p].projection;
            u.plane[p] = planes[p].plane;
        }
        u.params = glm::vec4(static_cast<float>(planes.size()), o.darkness, 0.0f, 0.0f);
        block_.write(u);
        host.drawItems(ItemFilter::Casters, program, [&](std::size_t i) {
            bool any = false;
            GLint self = -1;  // a receiver plane is not projected onto itself
            for (std::size_t p = 0; p < planes.size(); ++p) {
                if (planes[p].item == i) self = static_cast<GLint>(p);
                else any = any || above(planes[p].plane, frame.itemBounds[i]);
            }
            if (any && geometry) gl::programUniform1i(program.id(), 2, self);
            return any;
        });
    }

    // True when some corner of `box` is strictly on the light's side of `plane`.
    static bool above(const glm::vec4& plane, const Bounds& box) {
        for (int c = 0; c < 8; ++c) {
            const glm::vec3 corner((c & 1) ? box.hi.x : box.lo.x, (c & 2) ? box.hi.y : box.lo.y, (c & 4) ? box.hi.z : box.lo.z);
            if (glm::dot(plane, glm::vec4(corner, 1.0f)) > 0.0f) return true;
        }
        return false;
    }

    std::map<int, std::vector<Receiver>> receivers_;
    TechniqueBlock<shared::PlanarUniforms> block_;
};

} // namespace

TechniqueEntry planarTechnique() { return entryOf<PlanarShadow>("planar", "shadow_planar.glsl"); }

} // namespace shadowlab
