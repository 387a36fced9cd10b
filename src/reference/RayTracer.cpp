/// @file RayTracer.cpp
/// Exact shadow visibility with Embree 3: packets of 16 occlusion rays
/// (rtcOccluded16), traced in sample order on all hardware threads. The
/// BVH they are traced against is built in RayTracerBuild.cpp.
#include "reference/RayTracer.h"

#include "reference/AlphaCaster.h"
#include "reference/LightSetup.h"
#include "reference/ParallelChunks.h"
#include "reference/Sampling.h"

#include <shadowlab/Error.h>

#include <embree3/rtcore.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

namespace shadowlab::reference {

namespace {

constexpr int kPacket = 16;

// Shadow rays end this fraction short of a point/spot light (or a sample on
// it), so geometry that touches the light itself does not count as blocking.
constexpr float kTfarShrink = 1e-5f;

// Ray from o to a point on (or the centre of) a point/spot light: unit
// direction and tfar = distance minus a tiny epsilon. Returns false when o is
// at the point itself (nothing can be in between: visible).
bool rayToPoint(const glm::vec3& o, const glm::vec3& target, glm::vec3& dir, float& tfar) {
    const glm::vec3 v = target - o;
    const float dist = glm::length(v);
    if (!(dist > 0.0f)) return false;
    dir = v / dist;
    tfar = dist * (1.0f - kTfarShrink);
    return true;
}

// A packet of 16 shadow rays being filled; lanes without a ray stay invalid.
struct Packet {
    alignas(64) RTCRay16 ray;
    alignas(64) std::array<int, kPacket> valid;
    int lanes = 0; // number of valid lanes

    void clear() {
        valid.fill(0);
        lanes = 0;
    }
    void set(int lane, const glm::vec3& o, const glm::vec3& d, float tfar) {
        ray.org_x[lane] = o.x;
        ray.org_y[lane] = o.y;
        ray.org_z[lane] = o.z;
        ray.tnear[lane] = 0.0f; // the normal offset already left the surface
        ray.dir_x[lane] = d.x;
        ray.dir_y[lane] = d.y;
        ray.dir_z[lane] = d.z;
        ray.time[lane] = 0.0f;
        ray.tfar[lane] = tfar;
        ray.mask[lane] = 0xFFFFFFFFu;
        ray.id[lane] = static_cast<unsigned>(lane);  // translucentFilter's index into TransmitContext
        ray.flags[lane] = 0;
        valid[lane] = -1;
        ++lanes;
    }
    // rtcOccluded16 sets tfar to -inf for every ray that hit something.
    bool occluded(int lane) const { return ray.tfar[lane] == -std::numeric_limits<float>::infinity(); }
    void trace(RTCScene scene, RTCIntersectContext& context) {
        if (lanes > 0) rtcOccluded16(valid.data(), scene, &context, &ray);
    }
};

// One visibility() call: the light resolved once, the samples and what is
// written for each (by the tracing threads, each its own samples), shared
// by the hard and the soft path.
struct Trace {
    RTCScene scene;
    const LightSetup& setup;
    const std::vector<SurfaceSample>& samples;
    const VisibilityOptions& options;
    std::vector<float>& result;
    // Through translucent casters the light arrives coloured: the RGB
    // transmittance per sample, when asked for; `result` is its mean.
    std::vector<glm::vec3>* colour;

    // The first g^2 of a soft light's n rays per sample lie in a jittered
    // g x g grid, g = floor(sqrt n); the remainder are uniform.
    struct Strata {
        int n, grid, stratified;
    };

    static float mean(const glm::vec3& c) { return (c.r + c.g + c.b) / 3.0f; }

    // Sample i's transmittance t and its mean.
    void store(std::size_t i, const glm::vec3& t) const {
        result[i] = mean(t);
        if (colour) (*colour)[i] = t;
    }

    // Ray origin: the surface point moved off its surface by an amount that
    // depends on the point alone (offsetRayOrigin), or by a fixed distance.
    glm::vec3 originOf(const SurfaceSample& s) const {
        const float fixedOffset = options.normalOffset;
        return fixedOffset >= 0.0f ? s.position + fixedOffset * s.normal : offsetRayOrigin(s.position, s.normal);
    }

    // Each chunk: skipped once cancelled, counted when done.
    template <class Body>
    auto tracked(Body body) const {
        return [this, body](std::size_t begin, std::size_t end) {
            if (options.cancel && options.cancel->load(std::memory_order_relaxed)) return;
            body(begin, end);
            if (options.samplesDone) options.samplesDone->fetch_add(end - begin, std::memory_order_relaxed);
        };
    }
    void stopIfCancelled() const {
        if (options.cancel && options.cancel->load()) throw Error("RayTracer: tracing cancelled");
    }

    // Hard: one ray per sample, 16 consecutive samples per packet (raster
    // order: neighbouring origins, parallel or converging directions).
    void traceHard() const {
        parallelChunks(samples.size(), 4096, tracked([this](std::size_t begin, std::size_t end) { hardChunk(begin, end); }));
    }
    void hardChunk(std::size_t begin, std::size_t end) const {
        TransmitContext context;
        rtcInitIntersectContext(&context.base);
        context.base.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        Packet packet;
        std::array<std::size_t, kPacket> index{};
        for (std::size_t base = begin; base < end; base += kPacket) {
            packet.clear();
            const int count = static_cast<int>(std::min<std::size_t>(kPacket, end - base));
            for (int lane = 0; lane < count; ++lane) {
                const std::size_t i = base + static_cast<std::size_t>(lane);
                index[static_cast<std::size_t>(lane)] = i;
                const SurfaceSample& s = samples[i];
                if (!setup.reaches(s)) continue; // result stays 0
                const glm::vec3 o = originOf(s);
                glm::vec3 dir = setup.towardLight; // directional: to infinity
                float tfar = std::numeric_limits<float>::infinity();
                const bool traced = setup.type == LightType::Directional ||
                                    rayToPoint(o, setup.position, dir, tfar);
                if (traced) packet.set(lane, o, dir, tfar);
                else {
                    result[i] = 1.0f; // at the light: nothing in between
                    if (colour) (*colour)[i] = glm::vec3(1.0f);
                }
            }
            context.reset();
            packet.trace(scene, context.base);
            for (int lane = 0; lane < count; ++lane)
                if (packet.valid[static_cast<std::size_t>(lane)]) {
                    const glm::vec3 t = packet.occluded(lane) ? glm::vec3(0.0f) : context.transmit[static_cast<std::size_t>(lane)];
                    store(index[static_cast<std::size_t>(lane)], t);
                }
        }
    }

    // Soft: n rays per sample to points on the light, in packets of 16 from
    // one origin towards a small solid angle (coherent). Visibility = fraction
    // of unoccluded rays, a Monte-Carlo estimate of the visible part of the
    // light (by area for disks, by solid angle for the directional cone).
    void traceSoft() const {
        const int n = options.softSamples;
        const int grid = static_cast<int>(std::sqrt(static_cast<double>(n))); // floor(sqrt n)
        const int stratified = grid * grid;
        const std::size_t chunk = std::max<std::size_t>(1, 65536 / static_cast<std::size_t>(n));
        const Strata strata{n, grid, stratified};
        parallelChunks(samples.size(), chunk, tracked([this, strata](std::size_t begin, std::size_t end) {
            TransmitContext context;
            rtcInitIntersectContext(&context.base);
            context.base.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
            Packet packet;
            for (std::size_t i = begin; i < end; ++i) {
                const SurfaceSample& s = samples[i];
                if (!setup.reaches(s)) continue;
                store(i, softTransmittance(s, i, strata, context, packet));
            }
        }));
    }

    // Sample i's transmittance from the soft light: its n rays' summed, over n.
    glm::vec3 softTransmittance(const SurfaceSample& s, std::size_t i, const Strata& strata, TransmitContext& context,
                                Packet& packet) const {
        const int n = strata.n;
        const glm::vec3 o = originOf(s);
        // Point/spot: disk around the light's centre, facing the sample.
        glm::vec3 diskT{1.0f, 0.0f, 0.0f}, diskB{0.0f, 0.0f, 1.0f};
        if (setup.type != LightType::Directional) {
            const glm::vec3 d = s.position - setup.position;
            const float len = glm::length(d);
            orthonormalBasis(len > 0.0f ? d / len : glm::vec3(0.0f, 1.0f, 0.0f), diskT, diskB);
        }
        Pcg32 rng(options.seed, i);
        glm::vec3 unoccluded(0.0f);  // the rays' transmittance summed
        for (int k0 = 0; k0 < n; k0 += std::min(kPacket, n - k0)) {  // never past n: n near INT_MAX must not overflow
            packet.clear();
            const int count = std::min(kPacket, n - k0);
            for (int lane = 0; lane < count; ++lane) {
                glm::vec3 dir;
                float tfar = 0.0f;
                if (!softRay(k0 + lane, strata, rng, o, diskT, diskB, dir, tfar)) {
                    unoccluded += glm::vec3(1.0f); // on the light itself
                    continue;
                }
                packet.set(lane, o, dir, tfar);
            }
            context.reset();
            packet.trace(scene, context.base);
            for (int lane = 0; lane < count; ++lane)
                if (packet.valid[static_cast<std::size_t>(lane)] && !packet.occluded(lane)) unoccluded += context.transmit[static_cast<std::size_t>(lane)];
        }
        return unoccluded / static_cast<float>(n);
    }

    // Ray k of a sample at origin o towards the soft light (diskT, diskB: the
    // point/spot light's disk facing it): its direction and tfar. False when
    // its point on the light is o itself (nothing in between: unoccluded).
    bool softRay(int k, const Strata& strata, Pcg32& rng, const glm::vec3& o, const glm::vec3& diskT, const glm::vec3& diskB,
                 glm::vec3& dir, float& tfar) const {
        const int grid = strata.grid;
        // Jittered grid cell (k mod g, k div g) of the unit square
        // for the first g^2 samples, uniform for the remainder.
        float u = rng.uniform(), v = rng.uniform();
        if (k < strata.stratified) {
            u = (static_cast<float>(k % grid) + u) / static_cast<float>(grid);
            v = (static_cast<float>(k / grid) + v) / static_cast<float>(grid);
        }
        float radius = 0.0f, angle = 0.0f;
        concentricDisk(u, v, radius, angle); // uniform on the unit disk
        const float cosA = std::cos(angle), sinA = std::sin(angle);
        if (setup.type == LightType::Directional) {
            // Uniform in solid angle on the cap of half angle a:
            // 1 - cos(theta) = r^2 (1 - cos a) maps disk area to cap area.
            const float h = radius * radius * setup.oneMinusCosHalf; // 1 - cos(theta)
            const float sinTheta = std::sqrt(std::max(0.0f, h * (2.0f - h)));
            dir = (1.0f - h) * setup.towardLight +
                  sinTheta * (cosA * setup.coneT + sinA * setup.coneB);
            tfar = std::numeric_limits<float>::infinity();
            return true;
        }
        const glm::vec3 target =
            setup.position + setup.size * radius * (cosA * diskT + sinA * diskB);
        return rayToPoint(o, target, dir, tfar);
    }
};

} // namespace

std::vector<float> RayTracer::visibility(const Light& light, const std::vector<SurfaceSample>& samples,
                                         const VisibilityOptions& options) const {
    if (!scene_) throw Error("RayTracer: visibility() on a moved-from tracer");
    if (options.softSamples < 1)
        throw Error("RayTracer: VisibilityOptions::softSamples must be >= 1, got " +
                    std::to_string(options.softSamples));
    const LightSetup setup = makeLightSetup(light);
    RTCScene scene = scene_.get();
    std::vector<float> result(samples.size(), 0.0f);
    std::vector<glm::vec3>* colour = options.transmittance;
    if (colour) colour->assign(samples.size(), glm::vec3(0.0f));
    const Trace trace{scene, setup, samples, options, result, colour};
    if (setup.soft) trace.traceSoft();
    else trace.traceHard();
    trace.stopIfCancelled();
    return result;
}

} // namespace shadowlab::reference
