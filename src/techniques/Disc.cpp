// Technique "disc": each light's discs (the casting `disc` shapes, or the
// nodes the option names) as centres and semi-axes in world space, one
// uniform block; shaders/shadow_disc.glsl tests the segment to the light
// against each. It shares the base pass: no shadow pass, no map.
#include "techniques/Disc.h"

#include "core/Text.h"

#include <shadowlab/DiscOptions.h>
#include <shadowlab/Error.h>

#include "shadow_disc_shared.h"

#include <algorithm>
#include <map>

namespace shadowlab {

const OptionTable& discOptionTable() {
    static const OptionTable table =
        OptionTableFor<DiscOptions>("disc")
            .text(&DiscOptions::casters, "casters", "node names, comma-separated",
                  "the disc casters (disc shapes); empty: every casting node whose shape is a disc")
            .build();
    return table;
}

namespace {

struct Disc {
    glm::vec3 centre{0.0f}, a{0.0f}, b{0.0f};
};

// Item i as a disc: its mesh is a disc shape's fan (shapes::disc: every
// vertex in the object's XZ plane, one at the origin, the rest on one
// circle), the circle's radius from its vertices.
bool discOf(const FrameInfo& frame, std::size_t i, Disc& out) {
    const DrawItem& item = frame.items[i];
    const Mesh& mesh = frame.scene.meshes[static_cast<std::size_t>(item.mesh)];
    if (mesh.positions.size() < 4) return false;
    float radius = 0.0f, smallest = 1e30f;
    int centres = 0;
    for (const glm::vec3& p : mesh.positions) {
        if (p.y != 0.0f) return false;
        const float r = glm::length(glm::vec2(p.x, p.z));
        if (r == 0.0f) {
            ++centres;
            continue;
        }
        radius = std::max(radius, r);
        smallest = std::min(smallest, r);
    }
    if (centres != 1 || smallest < radius * (1.0f - 1e-5f)) return false;
    const glm::mat4& m = item.worldFromObject;
    out.centre = glm::vec3(m * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    out.a = glm::vec3(m * glm::vec4(radius, 0.0f, 0.0f, 0.0f));
    out.b = glm::vec3(m * glm::vec4(0.0f, 0.0f, radius, 0.0f));
    return true;
}

class DiscShadow final : public Technique {
public:
    void prepare(TechniqueHost&, const FrameInfo& frame, std::span<const int> lights) override {
        if (!ubo_) {
            ubo_ = gl::Buffer();
            glNamedBufferStorage(ubo_.id(), sizeof(shared::DiscUniforms), nullptr, GL_DYNAMIC_STORAGE_BIT);
        }
        Bounds scene;
        for (const Bounds& b : frame.itemBounds) scene.add(b);
        offset_ = scene.empty() ? 1e-5f : 1e-5f * std::max(glm::length(scene.size()), 1.0f);
        discs_.clear();
        for (int index : lights) {
            const DiscOptions& o = frame.scene.lights[static_cast<std::size_t>(index)].shadow.get<DiscOptions>();
            const std::string at = "lights[" + std::to_string(index) + "].shadow.disc.casters";
            std::vector<Disc>& list = discs_[index];
            const std::vector<std::string> names = text::splitNames(o.casters);
            Disc d;
            if (names.empty()) {
                for (std::size_t i = 0; i < frame.items.size(); ++i)
                    if (frame.items[i].castsShadows && discOf(frame, i, d)) list.push_back(d);
            } else {
                for (const std::string& name : names) {
                    bool found = false;
                    for (std::size_t i = 0; i < frame.items.size(); ++i) {
                        const int node = frame.items[i].node;
                        if (node < 0 || frame.scene.nodes[static_cast<std::size_t>(node)].name != name) continue;
                        found = true;
                        if (!discOf(frame, i, d)) throw Error(at + ": node '" + text::escapeControl(name) + "' is not a disc shape");
                        list.push_back(d);
                    }
                    if (!found) throw Error(at + ": no node named '" + text::escapeControl(name) + "'");
                }
            }
            if (list.size() > SL_DISC_MAX)
                throw Error(at + ": " + std::to_string(list.size()) + " discs, more than the " + std::to_string(SL_DISC_MAX) + " one light tests");
        }
    }

    void bindLightPass(TechniqueHost&, const FrameInfo&, const LightView& view) override {
        const std::vector<Disc>& list = discs_[view.index];
        shared::DiscUniforms u{};
        for (std::size_t k = 0; k < list.size(); ++k) {
            u.centre[k] = glm::vec4(list[k].centre, 1.0f);
            u.axisA[k] = glm::vec4(list[k].a, 0.0f);
            u.axisB[k] = glm::vec4(list[k].b, 0.0f);
        }
        u.light = view.light.type == LightType::Directional ? glm::vec4(-glm::normalize(view.light.direction), 0.0f) : glm::vec4(view.light.position, 1.0f);
        u.params = glm::vec4(static_cast<float>(list.size()), offset_, 0.0f, 0.0f);
        glNamedBufferSubData(ubo_.id(), 0, sizeof u, &u);
        glBindBufferBase(GL_UNIFORM_BUFFER, SL_BINDING_TECHNIQUE, ubo_.id());
    }

private:
    std::map<int, std::vector<Disc>> discs_;
    float offset_ = 1e-5f;
    gl::Buffer ubo_{gl::NoCreate};
};

} // namespace

TechniqueEntry discTechnique() {
    return {"disc", "exact shadows of flat discs in the light pass, no shadow pass or map (lecture 002 exercise 8.6.2-1)", &discOptionTable(),
            "shadow_disc.glsl", [] { return std::make_unique<DiscShadow>(); }};
}

} // namespace shadowlab
