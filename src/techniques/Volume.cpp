// Technique "volume": stencil shadow volumes (Ganovelli et al. §8.5). In the
// light's own pass: every caster drawn over GL_TRIANGLES_ADJACENCY through
// a geometry shader that extrudes its silhouette to infinity along the
// light's rays and caps it (shaders/shadow_volume.geom), counted in the
// stencil with two-sided operations, then the light added where the count
// is zero. The frame uses a projection with the far plane at infinity
// (needsInfiniteFar), so the back caps at infinity are never clipped.
//   depth-fail (default, "Carmack's reverse"): where a volume face is
//     behind the visible surface, back faces increment and front faces
//     decrement (wrapping): right even with the camera inside a volume;
//   depth-pass: where it is in front, front faces increment and back faces
//     decrement; needs no caps, but misses the faces behind the near plane
//     when the camera stands inside a volume.
// A mesh that is not closed (open or non-manifold edges, core/Adjacency.h)
// is noted once per frame (FrameStats::notes) and cast by its light-facing
// triangles with their open edges extruded (openMeshes "facing"), or by
// every triangle's own volume ("triangles").
#include "techniques/Volume.h"

#include "techniques/Stencil.h"
#include "techniques/TechniqueBlock.h"

#include "core/Adjacency.h"
#include "geometry/LightCamera.h"

#include <shadowlab/Error.h>
#include <shadowlab/VolumeOptions.h>

#include "gl/Calls.h"
#include "shadow_volume_shared.h"

#include <glm/gtc/matrix_transform.hpp>

#include <chrono>
#include <tuple>
#include <map>

namespace shadowlab {

namespace {

class ShadowVolume final : public Technique {
public:

    bool sharesBasePass(const Light&) const override { return false; }  // the light goes after the stencil
    bool needsInfiniteFar(const Light&) const override { return true; }

    void prepare(TechniqueHost& host, const FrameInfo& frame, std::span<const int> lights) override {
        // Open or non-manifold edges per mesh, found once per mesh contents.
        open_.resize(frame.scene.meshes.size(), Known{});
        for (std::size_t m = 0; m < frame.scene.meshes.size(); ++m) {
            const Mesh& mesh = frame.scene.meshes[m];
            Known& k = open_[m];
            if (k.positions != mesh.positions.data() || k.vertexCount != mesh.positions.size() || k.indexCount != mesh.indices.size()) {
                k = {mesh.positions.data(), mesh.positions.size(), mesh.indices.size(), openEdges(mesh.positions, mesh.indices)};
            }
        }
        // Per light, the casters that can shadow something the camera sees
        // (as for shadow maps: a floor with nothing visible under it is not one).
        casts_.clear();
        std::vector<std::uint8_t> any(frame.items.size(), 0);
        for (int index : lights) {
            const Light& light = frame.scene.lights[static_cast<std::size_t>(index)];
            const glm::vec4 towards = towardsLight(light);
            const glm::vec3 along = light.type == LightType::Directional ? glm::normalize(light.direction) : glm::vec3(0.0f, -1.0f, 0.0f);
            const glm::mat4 lightView = glm::lookAt(glm::vec3(0.0f), along, lightCameraUp(along));
            const FitInput in{frame.itemBounds, frame.items, frame.itemPlanes, frame.itemConvex, frame.clipFromWorld};
            std::vector<std::uint8_t>& casts = casts_[index] = castersThatMatter(towards, lightView, in);
            for (std::size_t i = 0; i < casts.size(); ++i) any[i] = any[i] | casts[i];
            // Shadow volumes follow geometry: an alpha-tested caster's holes
            // would be shadowed whole. Refused rather than silently wrong.
            for (std::size_t i = 0; i < casts.size(); ++i) {
                const DrawItem& item = frame.items[i];
                if (!casts[i] || item.material < 0) continue;
                const Material& material = frame.scene.materials[static_cast<std::size_t>(item.material)];
                if (material.alphaTested())
                    throw UnsupportedError("lights[" + std::to_string(index) + "].shadow.technique: volume: material '" + material.name +
                                "' is alpha-tested (alphaMode mask or blend) and casts into this light; shadow volumes follow geometry and would "
                                "shadow its holes whole: use technique map for this light, or make the material opaque");
            }
        }
        for (std::size_t i = 0; i < frame.items.size(); ++i) {
            const DrawItem& item = frame.items[i];
            if (!any[i]) continue;
            const std::size_t edges = open_[static_cast<std::size_t>(item.mesh)].edges;
            if (edges == 0) continue;
            const Mesh& mesh = frame.scene.meshes[static_cast<std::size_t>(item.mesh)];
            host.note("volume: mesh '" + (mesh.name.empty() ? "#" + std::to_string(item.mesh) : mesh.name) + "' is not closed: " +
                      std::to_string(edges) + " open or non-manifold edge(s); its shadow volume is built from " +
                      "its light-facing triangles with those edges extruded (lights[i].shadow.volume.openMeshes)");
        }
    }

    void renderLightPass(TechniqueHost& host, const FrameInfo& frame, const LightView& view) override {
        const VolumeOptions& o = view.light.shadow.get<VolumeOptions>();
        const bool depthFail = o.method != VolumeMethod::DepthPass;
        const bool book = o.method == VolumeMethod::Book;
        const shared::VolumeUniforms u = volumeUniforms(frame, view.light);
        block_.write(u);
        const gl::Program& program = host.program({{{GL_VERTEX_SHADER, "shadow_volume.vert"},
                                                    {GL_GEOMETRY_SHADER, "shadow_volume.geom"},
                                                    {GL_FRAGMENT_SHADER, "shadow_volume.frag"}},
                                                   std::string("#define CAPS ") + (depthFail ? "1" : "0") + "\n#define BOOK " + (book ? "1" : "0") + "\n"});
        clearStencil(host);
        gl::RenderState s = countingState(depthFail);
        const bool triangles = o.openMeshes == VolumeOpenMeshes::Triangles;
        std::size_t drawn = 0;
        const bool cpu = o.extrusion == VolumeExtrusion::Cpu;
        if (cpu) buildOnCpu(host, frame, view, triangles, depthFail);
        const gl::Program& cpuProgram = host.program({{{GL_VERTEX_SHADER, "shadow_volume_cpu.vert"}, {GL_FRAGMENT_SHADER, "shadow_volume.frag"}},
                                                      std::string("#define BOOK ") + (book ? "1" : "0") + "\n"});
        auto drawVolumes = [&] {
            const auto scope = host.timeScope("volumes");
            if (cpu) {
                cpuProgram.use();
                glBindVertexArray(cpuArray_.id());
                for (const CpuRange& r : cpuRanges_) {
                    host.bindItem(r.item);
                    glDrawArrays(GL_TRIANGLES, static_cast<GLint>(r.first), static_cast<GLsizei>(r.count));
                    drawn += frame.scene.meshes[static_cast<std::size_t>(frame.items[r.item].mesh)].triangleCount();
                }
                return;
            }
            host.drawItems(
                ItemFilter::Casters, program,
                [&](std::size_t i) {
                    if (!casts_[view.index][i]) return false;
                    const auto mesh = static_cast<std::size_t>(frame.items[i].mesh);
                    gl::programUniform1i(program.id(), 0, static_cast<int>(volumeMode(triangles, open_[mesh].edges > 0)));
                    const glm::dvec4 l = lightInObject(frame.items[i], view.light);
                    gl::programUniform4d(program.id(), 1, l.x, l.y, l.z, l.w);
                    drawn += frame.scene.meshes[mesh].triangleCount();
                    return true;
                },
                Topology::TrianglesAdjacency);
        };
        if (book) {
            // Ganovelli et al.'s §8.5 sequence: back faces (front faces culled) increment
            // where they fail the depth test, then front faces (back faces
            // culled) decrement there.
            s.stencilFront = s.stencilBack = {GL_ALWAYS, 0, 0xFF, 0xFF, GL_KEEP, GL_INCR_WRAP, GL_KEEP};
            s.cull = gl::Cull::Front;
            host.apply(s);
            drawVolumes();
            s.stencilFront = s.stencilBack = {GL_ALWAYS, 0, 0xFF, 0xFF, GL_KEEP, GL_DECR_WRAP, GL_KEEP};
            s.cull = gl::Cull::Back;
            host.apply(s);
            drawVolumes();
        } else {
            host.apply(s);
            drawVolumes();
        }
        host.count("triangles", static_cast<double>(drawn));
        gl::RenderState lit = host.litState();
        lit.stencil({GL_EQUAL, 0, 0xFF, 0x00});
        host.drawLit(lit);
        clearStencil(host);  // as the next light expects it
    }

private:
    // The volumes' uniforms for `light`: the light (its position with w = 1,
    // or the direction towards it with w = 0) and the book's extrusion
    // distance.
    static shared::VolumeUniforms volumeUniforms(const FrameInfo& frame, const Light& light) {
        shared::VolumeUniforms u{};
        u.light = towardsLight(light);
        // The book's extrusion: past every point of the scene seen from the light.
        Bounds scene;
        for (const Bounds& b : frame.itemBounds) scene.add(b);
        const float diagonal = scene.empty() ? 1.0f : glm::length(scene.size());
        const float fromLight = scene.empty() || u.light.w == 0.0f ? 0.0f : glm::length(scene.centre() - glm::vec3(u.light));
        u.params = glm::vec4(2.0f * (diagonal + fromLight) + 1.0f, 0.0f, 0.0f, 0.0f);
        return u;
    }

    // The state the volume faces are counted in the stencil with: no colour
    // or depth written, two-sided stencil operations for depth-fail (faces
    // behind the visible surface) or depth-pass (in front of it).
    static gl::RenderState countingState(bool depthFail) {
        gl::RenderState s;
        s.depthFunc = GL_LESS;  // a front cap lying in the lit surface fails: it is counted with the faces behind
        s.depthWrite = false;
        s.noColor();
        s.stencilTest = true;
        if (depthFail) {
            s.stencilBack = {GL_ALWAYS, 0, 0xFF, 0xFF, GL_KEEP, GL_INCR_WRAP, GL_KEEP};
            s.stencilFront = {GL_ALWAYS, 0, 0xFF, 0xFF, GL_KEEP, GL_DECR_WRAP, GL_KEEP};
        } else {
            s.stencilFront = {GL_ALWAYS, 0, 0xFF, 0xFF, GL_KEEP, GL_KEEP, GL_INCR_WRAP};
            s.stencilBack = {GL_ALWAYS, 0, 0xFF, 0xFF, GL_KEEP, GL_KEEP, GL_DECR_WRAP};
        }
        // Volume faces are pushed two depth units away from the camera, so
        // that a front cap never passes where it coincides with the lit
        // surface (1 left two pixels on the resting torus's terminator; 4
        // and more start to shift the shadows' edges).
        s.polygonOffset = true;
        s.offsetFactor = 0.0f;
        s.offsetUnits = 2.0f;
        return s;
    }

    // How a mesh's volume is built (shadow_volume.geom's `mode`): an open
    // mesh from its light-facing triangles, or every triangle its own volume
    // (openMeshes "triangles"); a closed one capped with the triangles that
    // face away from the light, which is right with the light inside it too.
    enum class Mode { Open = 0, PerTriangle = 1, Closed = 2 };
    static Mode volumeMode(bool trianglesForOpen, bool open) {
        return !open ? Mode::Closed : trianglesForOpen ? Mode::PerTriangle : Mode::Open;
    }

    // The light (position with w = 1, or the direction towards it with w =
    // 0) in the item's object space.
    static glm::dvec4 lightInObject(const DrawItem& item, const Light& light) {
        return glm::inverse(glm::dmat4(item.worldFromObject)) * glm::dvec4(towardsLight(light));
    }

    struct CpuVertex {
        glm::vec3 position;  ///< object space
        float extruded;      ///< 1: the copy at infinity (or the book's distance)
    };
    struct CpuRange {
        std::size_t item = 0, first = 0, count = 0;
    };

    // The geometry shader's work on the CPU (shaders/shadow_volume.geom says
    // what is emitted): silhouettes from the welded adjacency, side quads as
    // two triangles each (the strip's order), caps when counting depth-fail.
    void buildOnCpu(TechniqueHost& host, const FrameInfo& frame, const LightView& view, bool perTriangleForOpen, bool caps) {
        const auto start = std::chrono::steady_clock::now();
        cpuVertices_.clear();
        cpuRanges_.clear();
        std::size_t triangles = 0;
        for (std::size_t i = 0; i < frame.items.size(); ++i) {
            const DrawItem& item = frame.items[i];
            if (!item.castsShadows || !casts_[view.index][i]) continue;
            const auto m = static_cast<std::size_t>(item.mesh);
            const Mesh& mesh = frame.scene.meshes[m];
            if (adjacency_.size() <= m) adjacency_.resize(frame.scene.meshes.size());
            Adjacency& adj = adjacency_[m];
            if (adj.positions != mesh.positions.data() || adj.indexCount != mesh.indices.size()) {
                adj = {mesh.positions.data(), mesh.indices.size(), adjacencyIndices(mesh.positions, mesh.indices)};
            }
            CpuRange range{i, cpuVertices_.size(), 0};
            extrude(mesh, adj.indices, lightInObject(item, view.light), volumeMode(perTriangleForOpen, open_[m].edges > 0), caps);
            triangles += adj.indices.size() / 6;
            range.count = cpuVertices_.size() - range.first;
            if (range.count) cpuRanges_.push_back(range);
        }
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        host.count("cpuTriangles", static_cast<double>(triangles));
        if (seconds > 0.0) host.count("cpuTrianglesPerSecond", static_cast<double>(triangles) / seconds);
        if (!cpuArray_) {
            cpuArray_ = gl::VertexArray();
            gl::vertexArrayAttribFormat(cpuArray_.id(), 0, 3, GL_FLOAT, GL_FALSE, 0);
            gl::vertexArrayAttribFormat(cpuArray_.id(), 1, 1, GL_FLOAT, GL_FALSE, sizeof(glm::vec3));
            gl::vertexArrayAttribBinding(cpuArray_.id(), 0, 0);
            gl::vertexArrayAttribBinding(cpuArray_.id(), 1, 0);
            gl::enableVertexArrayAttrib(cpuArray_.id(), 0);
            gl::enableVertexArrayAttrib(cpuArray_.id(), 1);
        }
        // One buffer for the technique's life: glNamedBufferData gives it new
        // storage each frame (the driver keeps the old one while it is read).
        if (!cpuBuffer_) {
            cpuBuffer_ = gl::Buffer();
            gl::vertexArrayVertexBuffer(cpuArray_.id(), 0, cpuBuffer_.id(), 0, sizeof(CpuVertex));
        }
        gl::namedBufferData(cpuBuffer_.id(), static_cast<GLsizeiptr>(std::max<std::size_t>(1, cpuVertices_.size()) * sizeof(CpuVertex)),
                          cpuVertices_.empty() ? nullptr : cpuVertices_.data(), GL_STREAM_DRAW);
    }

    // One mesh's volume, appended to cpuVertices_: from its welded adjacency
    // x (six indices a triangle) and the light lo in its object space
    // (lightInObject), as shadow_volume.geom builds it in `mode`.
    void extrude(const Mesh& mesh, const std::vector<std::uint32_t>& x, const glm::dvec4& lo, Mode mode, bool caps) {
        // The facing test in object space and double precision, as the geometry shader does it.
        auto before = [&](std::uint32_t p, std::uint32_t q) {
            const glm::vec3 &u = mesh.positions[p], &v = mesh.positions[q];
            return u.x < v.x || (u.x == v.x && (u.y < v.y || (u.y == v.y && u.z < v.z)));
        };
        auto faces = [&](std::uint32_t i0, std::uint32_t i1, std::uint32_t i2) {
            // From the smallest corner on, as shadow_volume.geom does.
            if (before(i1, i0) && !before(i2, i1)) std::tie(i0, i1, i2) = std::tuple(i1, i2, i0);
            else if (before(i2, i0) && before(i2, i1)) std::tie(i0, i1, i2) = std::tuple(i2, i0, i1);
            const glm::dvec3 a(mesh.positions[i0]), b(mesh.positions[i1]), c(mesh.positions[i2]);
            const glm::dvec3 towards = lo.w > 0.5 ? glm::dvec3(lo) - a : glm::dvec3(lo);
            const glm::dvec3 n = glm::cross(b - a, c - a);
            return n.x * towards.x + n.y * towards.y + n.z * towards.z > 0.0;
        };
        auto put = [&](std::uint32_t k, float extruded) { cpuVertices_.push_back({mesh.positions[k], extruded}); };
        auto side = [&](std::uint32_t a, std::uint32_t b) {
            put(a, 0.0f), put(a, 1.0f), put(b, 0.0f);
            put(b, 0.0f), put(a, 1.0f), put(b, 1.0f);
        };
        for (std::size_t t = 0; t + 5 < x.size(); t += 6) {
            const bool lit = faces(x[t], x[t + 2], x[t + 4]);
            if (mode == Mode::Open && !lit) continue;
            const std::uint32_t a = x[t], b = lit ? x[t + 2] : x[t + 4], c = lit ? x[t + 4] : x[t + 2];
            if (mode == Mode::PerTriangle) {
                side(a, b), side(b, c), side(c, a);
            } else if (lit) {
                for (int e = 0; e < 3; ++e) {
                    const std::uint32_t p = x[t + 2 * e], q = x[t + (2 * e + 2) % 6], n = x[t + 2 * e + 1];
                    const bool open = mesh.positions[n] == mesh.positions[x[t + (2 * e + 4) % 6]];
                    if (open || !faces(p, n, q)) side(p, q);
                }
            }
            if (caps && !(mode == Mode::Closed && lit)) {
                put(a, 0.0f), put(b, 0.0f), put(c, 0.0f);
                put(a, 1.0f), put(c, 1.0f), put(b, 1.0f);
            }
        }
    }

    struct Adjacency {
        const glm::vec3* positions = nullptr;
        std::size_t indexCount = 0;
        std::vector<std::uint32_t> indices;
    };
    std::vector<Adjacency> adjacency_;
    std::vector<CpuVertex> cpuVertices_;
    std::vector<CpuRange> cpuRanges_;
    gl::VertexArray cpuArray_{gl::NoCreate};
    gl::Buffer cpuBuffer_{gl::NoCreate};


    struct Known {
        const glm::vec3* positions = nullptr;
        std::size_t vertexCount = 0, indexCount = 0;
        std::size_t edges = 0;
    };
    std::vector<Known> open_;
    std::map<int, std::vector<std::uint8_t>> casts_;
    TechniqueBlock<shared::VolumeUniforms> block_;
};

} // namespace

TechniqueEntry volumeTechnique() { return entryOf<ShadowVolume>("volume", "shadow_volume.glsl"); }

} // namespace shadowlab
