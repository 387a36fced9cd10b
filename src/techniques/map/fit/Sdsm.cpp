// Technique "map": fit "sdsm", the depth pre-pass and its reduction (fit/Sdsm.h).
#include "techniques/map/fit/Sdsm.h"

#include "techniques/map/passes/CasterDraw.h"

#include "geometry/LightCamera.h"
#include "gl/Calls.h"
#include "shadowlab_shared.h"

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

namespace shadowlab::map {

void SampleBounds::prepass(TechniqueHost& host, const FrameInfo& frame) {
    // The frame's own depth, drawn now and kept by the base pass (a shared
    // z-pre-pass: the base pass then shades the nearest surface only).
    if (!host.beginDepthPrepass()) return;  // drawn for another light this frame
    size_ = frame.viewport;
    gl::RenderState depthOnly;
    depthOnly.noColor();
    host.apply(depthOnly);
    // Alpha-tested surfaces through the fragment shader that cuts their
    // holes; the rest depth only, with no fragment shader.
    const auto masked = [&](std::size_t i) { return casterSurface(frame, i) == CasterSurface::Holes; };
    // Only what may be in view; large meshes as their boxes (kBoxedTriangles).
    const auto seen = [&](std::size_t i) { return mayIntersect(frame.clipFromWorld, frame.itemBounds[i]); };
    const auto large = [&](std::size_t i) {
        return frame.scene.meshes[static_cast<std::size_t>(frame.items[i].mesh)].triangleCount() > kBoxedTriangles;
    };
    boxed_.clear();
    host.drawItems(ItemFilter::Opaque, host.program({{{GL_VERTEX_SHADER, "scene.vert"}}, std::string()}), [&](std::size_t i) {
        if (masked(i) || !seen(i)) return false;
        if (large(i)) {
            boxed_.push_back(i);
            return false;
        }
        return true;
    });
    host.drawItems(ItemFilter::Opaque, host.program({{{GL_VERTEX_SHADER, "scene.vert"}, {GL_FRAGMENT_SHADER, "shadow_map_sdsm.frag"}}, std::string()}),
                   [&](std::size_t i) { return masked(i) && seen(i); });
}

namespace {

// Every covered pixel's window depth (uncovered ones, at depth 1, never count).
constexpr glm::vec2 kWholeDepth(0.0f, 0.99999994f);

} // namespace

void SampleBounds::draw(TechniqueHost& host, const FrameInfo& frame, const glm::mat4& lightFromWorld, const Windows& from, Targets& targets) {
    const int windows = from.count();
    const glm::ivec2 blocks = (size_ + (kBlock - 1)) / kBlock;
    if (!targets.fbo || targets.blocks != blocks) {
        targets.blocks = blocks;
        targets.lo.clear();
        targets.hi.clear();
        targets.fbo = gl::Framebuffer();
        std::vector<GLenum> buffers;
        for (int w = 0; w < windows; ++w) {
            for (std::vector<gl::Texture>* corner : {&targets.lo, &targets.hi}) {
                gl::Texture& t = corner->emplace_back(GL_TEXTURE_2D);
                gl::textureStorage2D(t.id(), 1, GL_RGBA32F, blocks.x, blocks.y);
            }
            // Window w's lowest corners at location 2w, its highest at 2w + 1.
            const auto lo = static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + 2 * w);
            gl::namedFramebufferTexture(targets.fbo.id(), lo, targets.lo.back().id(), 0);
            gl::namedFramebufferTexture(targets.fbo.id(), lo + 1, targets.hi.back().id(), 0);
            buffers.push_back(lo);
            buffers.push_back(lo + 1);
        }
        gl::namedFramebufferDrawBuffers(targets.fbo.id(), static_cast<GLsizei>(buffers.size()), buffers.data());
        gl::checkFramebuffer(targets.fbo, "sdsm reduction framebuffer");
    }
    glBindFramebuffer(GL_FRAMEBUFFER, targets.fbo.id());
    glViewport(0, 0, blocks.x, blocks.y);
    host.apply(gl::RenderState{});
    const gl::Program& program =
        host.program({{{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "shadow_map_sdsm_reduce.frag"}},
                      "#define SDSM_WINDOWS " + std::to_string(windows) + "\n#define SDSM_WINDOWS_FROM_FIT " + (from.fit ? "1" : "0") + "\n"});
    program.use();
    // Window (pixel x, y, depth 0..1) to clip: x 2 / width - 1, y 2 / height - 1, z 2 d - 1.
    glm::mat4 clipFromWindow(1.0f);
    clipFromWindow[0][0] = 2.0f / static_cast<float>(size_.x);
    clipFromWindow[1][1] = 2.0f / static_cast<float>(size_.y);
    clipFromWindow[2][2] = 2.0f;
    clipFromWindow[3] = glm::vec4(-1.0f, -1.0f, -1.0f, 1.0f);
    const glm::mat4 lightFromWindow = lightFromWorld * glm::inverse(frame.clipFromWorld) * clipFromWindow;
    gl::programUniformMatrix4fv(program.id(), 0, 1, GL_FALSE, &lightFromWindow[0][0]);
    gl::programUniform2i(program.id(), 2, size_.x, size_.y);
    if (!sampler_) {
        // Nearest; the reduction gathers 2x2 texels: past the frame's edge, the edge.
        sampler_ = gl::Sampler();
        glSamplerParameteri(sampler_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glSamplerParameteri(sampler_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glSamplerParameteri(sampler_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glSamplerParameteri(sampler_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    gl::bindTextureUnit(SL_UNIT_SHADOW_FIRST, host.frameDepth().id());
    glBindSampler(SL_UNIT_SHADOW_FIRST, sampler_.id());
    if (from.fit) {
        gl::programUniform1i(program.id(), 3, from.firstSlice);
        gl::programUniform1i(program.id(), 4, from.sliceCount);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_STORAGE_SDSM_FIT, from.fit->id());
    } else {
        gl::programUniform2fv(program.id(), 3, windows, &from.depths[0][0]);
    }
    host.drawFullscreenTriangle();
    gl::bindTextureUnit(SL_UNIT_SHADOW_FIRST, 0);
    glBindSampler(SL_UNIT_SHADOW_FIRST, 0);
}

void SampleBounds::uploadBoxes(const FrameInfo& frame, const std::vector<Bounds>& casters, bool withBoxed) {
    // The casters' boxes in the light's view, lo and hi each; then the
    // large meshes' in the world (none at all: one empty box, the buffer never empty).
    std::vector<glm::vec4> boxes;
    for (const Bounds& b : casters) {
        boxes.emplace_back(b.lo, 0.0f);
        boxes.emplace_back(b.hi, 0.0f);
    }
    if (withBoxed)
        for (const std::size_t i : boxed_) {
            boxes.emplace_back(frame.itemBounds[i].lo, 0.0f);
            boxes.emplace_back(frame.itemBounds[i].hi, 0.0f);
        }
    if (boxes.empty()) boxes = {glm::vec4(1.0f), glm::vec4(-1.0f)};
    const auto bytes = static_cast<GLsizeiptr>(boxes.size() * sizeof(glm::vec4));
    if (!casters_ || castersBytes_ < bytes) {
        casters_ = gl::Buffer();
        castersBytes_ = std::max<GLsizeiptr>(bytes, 64 * static_cast<GLsizeiptr>(sizeof(glm::vec4)));
        gl::namedBufferStorage(casters_.id(), castersBytes_, nullptr, GL_DYNAMIC_STORAGE_BIT);
    }
    gl::namedBufferSubData(casters_.id(), 0, bytes, boxes.data());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_STORAGE_SDSM_CASTERS, casters_.id());
}

namespace {

// The fit's settings both of shadow_map_sdsm_fit.comp's uses take
// (locations 0 and 4 to 7, and 8 to 13 when warped).
void setFitUniforms(GLuint id, const GpuFitInput& in) {
    gl::programUniformMatrix4fv(id, 0, 1, GL_FALSE, &in.lightView[0][0]);
    gl::programUniform1f(id, 4, in.diagonal);
    gl::programUniform1f(id, 5, in.size);
    gl::programUniform1f(id, 6, in.padding);
    gl::programUniform1i(id, 7, static_cast<GLint>(in.casters.size()));
    if (in.warped) {
        // The samples' box into the turned view, the view back to the world (as the CPU inverts it), the warp.
        const glm::mat4 turnedFromSamples = in.lightView * glm::inverse(in.samplesView), worldFromTurned = glm::inverse(in.lightView);
        gl::programUniformMatrix4fv(id, 8, 1, GL_FALSE, &worldFromTurned[0][0]);
        gl::programUniformMatrix4fv(id, 9, 1, GL_FALSE, &turnedFromSamples[0][0]);
        gl::programUniform3fv(id, 10, 1, &in.eye.x);
        gl::programUniform3fv(id, 11, 1, &in.forward.x);
        gl::programUniform1f(id, 12, in.warpNear);
        gl::programUniform1f(id, 13, in.sinGamma);
    }
}

std::string fitDefines(const GpuFitInput& in, bool slice) {
    return std::string("#define SDSM_WARP ") + (in.warped ? "1" : "0") + "\n#define SDSM_SLICE " + (slice ? "1" : "0") + "\n";
}

} // namespace

void SampleBounds::fitOnGpu(TechniqueHost& host, const FrameInfo& frame, const GpuFitInput& in, const gl::Buffer& out) {
    const bool cascades = in.cascades > 1;
    // Cascades: the view's own space, whose z is minus the distance along the view.
    const glm::mat4 space = cascades ? frame.viewFromWorld : in.samplesView;
    draw(host, frame, space, {{kWholeDepth}}, one_);
    Bounds boxed;
    addBoxed(boxed, frame, space);
    const gl::Program& program =
        cascades ? host.program({{{GL_COMPUTE_SHADER, "shadow_map_sdsm_cascades.comp"}}, std::string("#define SDSM_STABILIZE ") + (in.stabilize ? "1\n" : "0\n")})
                 : host.program({{{GL_COMPUTE_SHADER, "shadow_map_sdsm_fit.comp"}}, fitDefines(in, false)});
    program.use();
    const GLuint id = program.id();
    gl::programUniform2i(id, 1, one_.blocks.x, one_.blocks.y);
    const glm::vec3 lo = boxed.empty() ? glm::vec3(1.0f) : boxed.lo, hi = boxed.empty() ? glm::vec3(-1.0f) : boxed.hi;
    gl::programUniform3fv(id, 2, 1, &lo.x);
    gl::programUniform3fv(id, 3, 1, &hi.x);
    if (cascades) {
        gl::programUniformMatrix4fv(id, 0, 1, GL_FALSE, &in.samplesView[0][0]);
        gl::programUniform1f(id, 4, in.diagonal);
        gl::programUniform1f(id, 5, in.size);
        gl::programUniform1f(id, 6, in.padding);
        gl::programUniform1i(id, 7, in.cascades);
        gl::programUniform4fv(id, 8, 1, &in.camera.x);
        gl::programUniform3fv(id, 9, 1, &in.eye.x);
        gl::programUniform3fv(id, 10, 1, &in.forward.x);
        gl::programUniform3fv(id, 11, 1, &in.right.x);
        gl::programUniform3fv(id, 12, 1, &in.up.x);
        gl::programUniform1f(id, 13, in.reach);
        gl::programUniform1f(id, 14, in.lambda);
        gl::programUniform3fv(id, 15, 1, &in.scene.lo.x);
        gl::programUniform3fv(id, 16, 1, &in.scene.hi.x);
        if (!in.given.empty()) gl::programUniform1fv(id, 17, static_cast<GLsizei>(in.given.size()), in.given.data());
        gl::programUniform1i(id, 24, static_cast<GLint>(in.given.size()));
        gl::programUniform2f(id, 25, in.splitRange.x, in.splitRange.y);
        if (in.stabilize) gl::programUniform4fv(id, 28, 1, &in.receiversWindow.x);
        if (!in.stabilize) {
            gl::programUniformMatrix4fv(id, 26, 1, GL_FALSE, &frame.clipFromView[0][0]);
            gl::programUniform1f(id, 27, in.blend);
        }
    } else {
        uploadBoxes(frame, in.casters, false);
        setFitUniforms(id, in);
    }
    gl::bindTextureUnit(SL_UNIT_SHADOW_FIRST, one_.lo.front().id());
    gl::bindTextureUnit(SL_UNIT_SHADOW_FIRST + 1, one_.hi.front().id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_STORAGE_SDSM_FIT, out.id());
    gl::dispatchCompute(1, 1, 1);
    // The block takes the fit by a buffer copy (MapBlock::upload), the
    // slices' reduction its windows; the next frame's pass reads the depths it keeps there.
    gl::memoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    gl::bindTextureUnit(SL_UNIT_SHADOW_FIRST, 0);
    gl::bindTextureUnit(SL_UNIT_SHADOW_FIRST + 1, 0);
    if (cascades && !in.stabilize) fitSlices(host, frame, in, out);
}

void SampleBounds::fitSlices(TechniqueHost& host, const FrameInfo& frame, const GpuFitInput& in, const gl::Buffer& out) {
    // Each slice's samples in the light's view (the one map's space), kSlicesAPass slices a reduction.
    uploadBoxes(frame, in.casters, true);
    // The fit's settings once; each group's reduction draws with its own program in between.
    const gl::Program& program = host.program({{{GL_COMPUTE_SHADER, "shadow_map_sdsm_fit.comp"}}, fitDefines(in, true)});
    const GLuint id = program.id();
    setFitUniforms(id, in);
    const glm::mat4 samplesFromClip = in.samplesView * glm::inverse(frame.clipFromWorld);
    gl::programUniformMatrix4fv(id, 15, 1, GL_FALSE, &samplesFromClip[0][0]);
    gl::programUniform1i(id, 16, static_cast<GLint>(boxed_.size()));
    gl::programUniformMatrix4fv(id, 17, 1, GL_FALSE, &in.samplesView[0][0]);
    for (int first = 0; first < in.cascades; first += kSlicesAPass) {
        draw(host, frame, in.samplesView, Windows{{}, &out, first, in.cascades}, slices_);
        program.use();
        gl::programUniform2i(id, 1, slices_.blocks.x, slices_.blocks.y);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SL_STORAGE_SDSM_FIT, out.id());
        for (int w = 0; w < kSlicesAPass && first + w < in.cascades; ++w) {
            gl::programUniform1i(id, 14, first + w);
            gl::bindTextureUnit(SL_UNIT_SHADOW_FIRST, slices_.lo[static_cast<std::size_t>(w)].id());
            gl::bindTextureUnit(SL_UNIT_SHADOW_FIRST + 1, slices_.hi[static_cast<std::size_t>(w)].id());
            gl::dispatchCompute(1, 1, 1);
        }
        gl::memoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    }
    gl::bindTextureUnit(SL_UNIT_SHADOW_FIRST, 0);
    gl::bindTextureUnit(SL_UNIT_SHADOW_FIRST + 1, 0);
}

void SampleBounds::addBoxed(Bounds& b, const FrameInfo& frame, const glm::mat4& lightFromWorld) const {
    // The large meshes left out of the pre-pass: their boxes, cut to the view's frustum.
    if (boxed_.empty()) return;
    const Bounds view = frustumBounds(frame.clipFromWorld, lightFromWorld);
    for (const std::size_t i : boxed_) {
        b.add(frame.itemBounds[i].transformed(lightFromWorld).cutTo(view));  // add() skips an empty box
    }
}

std::vector<glm::mat4> readFittedClips(const gl::Buffer& fit, std::size_t cascades) {
    SdsmFit f;
    gl::getNamedBufferSubData(fit.id(), 0, sizeof f, &f);
    if (cascades <= 1) return {f.clipFromWorld};
    return {f.cascadeClip, f.cascadeClip + std::min<std::size_t>(cascades, SL_MAP_MAX_CASCADES)};
}

GpuFit::~GpuFit() {
    if (fence_) glDeleteSync(fence_);
}

gl::Buffer& GpuFit::buffer() {
    if (!fit_) {
        fit_ = gl::Buffer();
        const SdsmFit zero{};
        gl::namedBufferStorage(fit_.id(), sizeof zero, &zero, 0);
    }
    return fit_;
}

float GpuFit::seenFar() {
    if (fence_) {
        const GLenum status = glClientWaitSync(fence_, 0, 0);  // a look, no wait
        if (status == GL_ALREADY_SIGNALED || status == GL_CONDITION_SATISFIED) {
            seenFar_ = *mapped_;
            glDeleteSync(fence_);
            fence_ = nullptr;
        }
    }
    return seenFar_;
}

void GpuFit::readSeenFarLater() {
    if (fence_) return;  // the copy before has not landed: it is read first
    if (!copy_) {
        copy_ = gl::Buffer();
        const GLbitfield flags = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
        gl::namedBufferStorage(copy_.id(), sizeof(float), nullptr, flags);
        mapped_ = static_cast<const float*>(gl::mapNamedBufferRange(copy_.id(), 0, sizeof(float), flags));
    }
    gl::copyNamedBufferSubData(buffer().id(), copy_.id(), offsetof(SdsmFit, seenFar), 0, sizeof(float));
    fence_ = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
}

} // namespace shadowlab::map
