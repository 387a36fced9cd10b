/// @file RayTracer.cpp
/// Exact shadow visibility with Embree 3: packets of 16 occlusion rays
/// (rtcOccluded16), traced in sample order on all hardware threads.
#include "reference/RayTracer.h"

#include <shadowlab/Error.h>

#include "light_reach.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <system_error>
#include <thread>

#if defined(__SSE__) || defined(_M_X64)
#include <xmmintrin.h>
#define SHADOWLAB_HAVE_MXCSR 1
#endif

namespace shadowlab::reference {

void RayTracer::DeviceDeleter::operator()(RTCDeviceTy* device) const { rtcReleaseDevice(device); }
void RayTracer::SceneDeleter::operator()(RTCSceneTy* scene) const { rtcReleaseScene(scene); }

struct RayTracer::AlphaCaster {
    std::vector<glm::vec2> uvs;           ///< per vertex (empty: all (0, 0))
    std::vector<std::uint32_t> indices;   ///< three per triangle, as the geometry's
    float alpha = 1.0f, cutoff = 0.5f;
    bool translucent = false;             ///< blend: light passes, filtered by transmittanceAt()
    glm::vec3 baseColor{1.0f};            ///< linear
    const ImageRGBA8* texture = nullptr;  ///< the base-colour texture (the tracer's copy), or none

    // The texture at uv as the GPU reads it (alpha_test.h: textureLod level
    // 0, bilinear, repeating), each texel through `fetch` (its bytes).
    template <class Fetch>
    auto bilinear(glm::vec2 uv, const Fetch& fetch) const {
        const int w = texture->width, h = texture->height;
        const float x = uv.x * static_cast<float>(w) - 0.5f, y = uv.y * static_cast<float>(h) - 0.5f;
        const float fx0 = std::floor(x), fy0 = std::floor(y), fx = x - fx0, fy = y - fy0;
        const auto at = [&](float xf, float yf) {
            const long xi = ((static_cast<long>(xf) % w) + w) % w, yi = ((static_cast<long>(yf) % h) + h) % h;
            return fetch(&texture->pixels[(static_cast<std::size_t>(yi) * static_cast<std::size_t>(w) + static_cast<std::size_t>(xi)) * 4]);
        };
        const auto top = at(fx0, fy0) + fx * (at(fx0 + 1.0f, fy0) - at(fx0, fy0));
        const auto bottom = at(fx0, fy0 + 1.0f) + fx * (at(fx0 + 1.0f, fy0 + 1.0f) - at(fx0, fy0 + 1.0f));
        return top + fy * (bottom - top);
    }
    bool hasTexture() const { return texture && texture->width > 0 && texture->height > 0; }
    // Its alpha at uv: the bytes / 255.
    float textureAlpha(glm::vec2 uv) const {
        return bilinear(uv, [](const std::uint8_t* p) { return static_cast<float>(p[3]) / 255.0f; });
    }
    // Its colour at uv, decoded from sRGB as the GPU's SRGB8_ALPHA8 is.
    glm::vec4 textureAt(glm::vec2 uv) const {
        const auto linear = [](std::uint8_t c) {
            const float v = static_cast<float>(c) / 255.0f;
            return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
        };
        return bilinear(uv, [&](const std::uint8_t* p) { return glm::vec4(linear(p[0]), linear(p[1]), linear(p[2]), static_cast<float>(p[3]) / 255.0f); });
    }
    glm::vec2 uvAt(unsigned prim, float u, float v) const {
        if (uvs.empty()) return glm::vec2(0.0f);
        const std::size_t base = static_cast<std::size_t>(prim) * 3;
        return (1.0f - u - v) * uvs[indices[base]] + u * uvs[indices[base + 1]] + v * uvs[indices[base + 2]];
    }
    // A translucent (blend) surface's transmittance at barycentrics (u, v)
    // of triangle `prim`: white through its clear parts, its colour where it
    // is opaque (alpha_test.h's surfaceTransmittance on the GPU).
    glm::vec3 transmittanceAt(unsigned prim, float u, float v) const {
        glm::vec4 c(baseColor, alpha);
        if (hasTexture()) c *= textureAt(uvAt(prim, u, v));
        return glm::mix(glm::vec3(1.0f), glm::vec3(c), c.a);
    }
    // Whether the surface is there at barycentrics (u, v) of triangle `prim`.
    bool solidAt(unsigned prim, float u, float v) const {
        const float a = alpha * (hasTexture() ? textureAlpha(uvAt(prim, u, v)) : 1.0f);
        return a >= cutoff;
    }
};

namespace {

// The intersect context every packet is traced with: the transmittance each
// ray (its RTCRay::id, a lane of the packet) has gathered through translucent
// casters, and the translucent triangles it has already crossed (Embree may
// report a triangle more than once with spatial splits).
struct TransmitContext {
    RTCIntersectContext base;  // first: the filter gets a pointer to it
    std::array<glm::vec3, 16> transmit;
    std::array<std::array<std::uint64_t, 8>, 16> crossed;
    std::array<int, 16> crossedCount;
    void reset() {
        transmit.fill(glm::vec3(1.0f));
        crossedCount.fill(0);
    }
};

// Embree's occlusion filter for a translucent caster: the ray goes on,
// filtered by the surface's transmittance (once per triangle crossed).
void translucentFilter(const RTCFilterFunctionNArguments* args) {
    const auto* caster = static_cast<const RayTracer::AlphaCaster*>(args->geometryUserPtr);
    auto* context = reinterpret_cast<TransmitContext*>(const_cast<RTCIntersectContext*>(args->context));
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        args->valid[i] = 0;
        const unsigned lane = RTCRayN_id(args->ray, args->N, i) % 16u;
        const std::uint64_t key = (static_cast<std::uint64_t>(RTCHitN_geomID(args->hit, args->N, i)) << 32) | RTCHitN_primID(args->hit, args->N, i);
        auto& crossed = context->crossed[lane];
        int& count = context->crossedCount[lane];
        if (std::find(crossed.begin(), crossed.begin() + count, key) != crossed.begin() + count) continue;
        if (count < static_cast<int>(crossed.size())) crossed[static_cast<std::size_t>(count++)] = key;
        context->transmit[lane] *= caster->transmittanceAt(RTCHitN_primID(args->hit, args->N, i), RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i));
    }
}

// Embree's occlusion filter for an alpha-tested caster: a hit in one of its
// holes is rejected, the ray goes on.
void alphaFilter(const RTCFilterFunctionNArguments* args) {
    const auto* caster = static_cast<const RayTracer::AlphaCaster*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
        if (!caster->solidAt(prim, RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i))) args->valid[i] = 0;
    }
}

constexpr int kPacket = 16;

// Shadow rays end this fraction short of a point/spot light (or a sample on
// it), so geometry that touches the light itself does not count as blocking.
constexpr float kTfarShrink = 1e-5f;

const char* errorText(RTCError code) {
    switch (code) {
    case RTC_ERROR_NONE: return "no error";
    case RTC_ERROR_UNKNOWN: return "unknown error";
    case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU (Embree needs at least SSE2)";
    case RTC_ERROR_CANCELLED: return "cancelled";
    }
    return "unrecognised error code";
}

// Collects the text of the Embree errors raised on a device while it lives
// (the constructor), and detaches itself on every exit path.
class ErrorCapture {
public:
    explicit ErrorCapture(RTCDevice device) : device_(device) { rtcSetDeviceErrorFunction(device_, record, &text_); }
    ~ErrorCapture() { rtcSetDeviceErrorFunction(device_, nullptr, nullptr); }
    ErrorCapture(const ErrorCapture&) = delete;
    ErrorCapture& operator=(const ErrorCapture&) = delete;
    const std::string& text() const { return text_; }

private:
    static void record(void* userPtr, RTCError code, const char* str) {
        auto* message = static_cast<std::string*>(userPtr);
        if (!message->empty()) *message += "; ";
        *message += errorText(code);
        if (str && *str) {
            *message += ": ";
            *message += str;
        }
    }
    RTCDevice device_;
    std::string text_;
};

// Embree recommends flush-to-zero and denormals-are-zero while tracing; set
// for the lifetime of a worker and restore the thread's previous mode.
class FlushDenormalsGuard {
public:
#ifdef SHADOWLAB_HAVE_MXCSR
    FlushDenormalsGuard() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ | 0x8040u); } // FTZ | DAZ
    ~FlushDenormalsGuard() { _mm_setcsr(saved_); }
private:
    unsigned saved_;
#endif
public:
    FlushDenormalsGuard(const FlushDenormalsGuard&) = delete;
    FlushDenormalsGuard& operator=(const FlushDenormalsGuard&) = delete;
};

// Runs fn(begin, end) over [0, count) in chunks of `chunk`, handed out with an
// atomic counter to one worker per hardware thread (the caller is one of them).
template <class Fn>
void parallelChunks(std::size_t count, std::size_t chunk, const Fn& fn) {
    if (count == 0) return;
    const std::size_t chunks = (count + chunk - 1) / chunk;
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
        FlushDenormalsGuard ftz;
        for (;;) {
            const std::size_t c = next.fetch_add(1, std::memory_order_relaxed);
            if (c >= chunks) break;
            fn(c * chunk, std::min(count, (c + 1) * chunk));
        }
    };
    const std::size_t threads =
        std::min<std::size_t>(std::max(1u, std::thread::hardware_concurrency()), chunks);
    std::vector<std::jthread> helpers;
    helpers.reserve(threads - 1);
    for (std::size_t t = 1; t < threads; ++t) {
        try {
            helpers.emplace_back(worker);
        } catch (const std::system_error&) {
            break; // fewer threads: the remaining workers take all chunks
        }
    }
    worker();
} // helpers join here

// Per-sample random numbers: a PCG32 stream (O'Neill 2014) whose state comes
// from splitmix64(seed, sample index), so every sample's jitter is fixed by
// the seed alone, whatever thread traces it.
class Pcg32 {
public:
    Pcg32(unsigned seed, std::uint64_t index) {
        std::uint64_t z = (std::uint64_t(seed) << 32 ^ index) + 0x9E3779B97F4A7C15ull;
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        state_ = z ^ (z >> 31);
        next();
    }
    std::uint32_t next() {
        const std::uint64_t old = state_;
        state_ = old * 6364136223846793005ull + 1442695040888963407ull;
        const auto xorshifted = std::uint32_t(((old >> 18u) ^ old) >> 27u);
        const auto rot = std::uint32_t(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
    }
    /// Uniform in [0, 1): 24 random mantissa bits.
    float uniform() { return float(next() >> 8) * 0x1.0p-24f; }
private:
    std::uint64_t state_ = 0;
};

// Orthonormal basis around unit w (Duff et al. 2017, "Building an
// Orthonormal Basis, Revisited"): no branch on a threshold, no singularity.
void orthonormalBasis(const glm::vec3& w, glm::vec3& t, glm::vec3& b) {
    const float sign = std::copysign(1.0f, w.z);
    const float a = -1.0f / (sign + w.z);
    const float c = w.x * w.y * a;
    t = glm::vec3(1.0f + sign * w.x * w.x * a, sign * c, -sign * w.x);
    b = glm::vec3(c, sign + w.y * w.y * a, -w.y);
}

// Shirley-Chiu concentric map of the unit square onto the unit disk:
// area-preserving (uniform in, uniform out) and low-distortion, so jittered
// grid strata stay compact on the disk. Returns polar (radius, angle).
void concentricDisk(float u, float v, float& radius, float& angle) {
    const float a = 2.0f * u - 1.0f;
    const float b = 2.0f * v - 1.0f;
    constexpr float quarterPi = std::numbers::pi_v<float> / 4.0f;
    if (a == 0.0f && b == 0.0f) {
        radius = 0.0f;
        angle = 0.0f;
    } else if (std::abs(a) > std::abs(b)) {
        radius = a;
        angle = quarterPi * (b / a);
    } else {
        radius = b;
        angle = 2.0f * quarterPi - quarterPi * (a / b);
    }
}

// Everything a ray needs to know about the light, resolved once per call.
struct LightSetup {
    LightType type = LightType::Directional;
    glm::vec3 position{0.0f};
    glm::vec3 towardLight{0.0f, 1.0f, 0.0f}; // directional: -direction, unit
    glm::vec3 axis{0.0f, -1.0f, 0.0f};       // spot: direction, unit
    glm::vec3 coneT{1.0f, 0.0f, 0.0f};       // directional soft: basis around towardLight
    glm::vec3 coneB{0.0f, 0.0f, 1.0f};
    float cosOuter = -1.0f;
    float range = 0.0f;
    float size = 0.0f;              // point/spot: disk radius
    float oneMinusCosHalf = 0.0f;   // directional: 1 - cos(half angular diameter)
    bool soft = false;

    int shaderType = SL_LIGHT_DIRECTIONAL; // the SL_LIGHT_* code of `type`

    // The sample can receive this light at all: valid, within its reach
    // (shared::slLightReaches, the definition lighting.frag uses: spot cone,
    // range) and facing its centre on the geometric normal.
    bool reaches(const SurfaceSample& s) const {
        if (!s.valid) return false;
        if (!shared::slLightReaches(shaderType, position, axis, range, cosOuter, s.position)) return false;
        const glm::vec3 toLight = type == LightType::Directional ? towardLight : position - s.position;
        return glm::dot(s.normal, toLight) > 0.0f;
    }
};

LightSetup makeLightSetup(const Light& light) {
    LightSetup setup;
    setup.type = light.type;
    setup.position = light.position;
    setup.range = light.range;
    setup.soft = light.size > 0.0f;
    setup.shaderType = light.type == LightType::Directional ? SL_LIGHT_DIRECTIONAL
                       : light.type == LightType::Spot      ? SL_LIGHT_SPOT
                                                            : SL_LIGHT_POINT;
    const std::string who = "RayTracer: light '" + light.name + "': ";
    if (light.type != LightType::Point) {
        const float len = glm::length(light.direction);
        if (!(len > 0.0f) || !std::isfinite(len))
            throw Error(who + "direction must be a finite nonzero vector");
        setup.axis = light.direction / len;
        setup.towardLight = -setup.axis;
    }
    if (light.type == LightType::Spot)
        setup.cosOuter = std::cos(glm::radians(light.outerConeDeg));
    if (setup.soft) {
        if (light.type == LightType::Directional) {
            // size = angular diameter in degrees; the half angle is at most pi.
            const float half = std::min(glm::radians(light.size) * 0.5f, std::numbers::pi_v<float>);
            setup.oneMinusCosHalf = 1.0f - std::cos(half);
            orthonormalBasis(setup.towardLight, setup.coneT, setup.coneB);
        } else {
            setup.size = light.size;
        }
    }
    return setup;
}

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

} // namespace

glm::vec3 offsetRayOrigin(const glm::vec3& p, const glm::vec3& n) {
    // Wachter and Binder, "A Fast and Robust Method for Avoiding
    // Self-Intersection", Ray Tracing Gems ch. 6 (2019): move each coordinate
    // by kIntScale * n_i units in its own last place (integer arithmetic on
    // the float's bits, so the step cannot be rounded away); near zero, where
    // ulps vanish, by kFloatScale * n_i scene units instead.
    constexpr float kOrigin = 1.0f / 32.0f;
    constexpr float kFloatScale = 1.0f / 65536.0f;
    constexpr float kIntScale = 256.0f;
    glm::vec3 o;
    for (int i = 0; i < 3; ++i) {
        if (std::abs(p[i]) < kOrigin) {
            o[i] = p[i] + kFloatScale * n[i];
            continue;
        }
        // Away from zero the bits of |p| stay far from the sign bit and
        // from wrapping, so the step is computed on unsigned bits (defined
        // modular arithmetic; -0.0f, whose bits are INT_MIN, never gets here).
        const auto ulps = static_cast<std::int32_t>(kIntScale * n[i]);
        const std::uint32_t step = static_cast<std::uint32_t>(p[i] < 0.0f ? -ulps : ulps);
        o[i] = std::bit_cast<float>(std::bit_cast<std::uint32_t>(p[i]) + step);
    }
    // Plus a push along the normal for the rasterizer's error: p is a
    // position the GPU interpolated into an RGBA32F target, which can lie a
    // few ulps of the largest coordinate (more where the plane equation
    // cancels) below the triangle Embree sees. 2^-16 of the largest
    // coordinate is 128 of its ulps; CompareGLTest measured at most 5.7 on a
    // large tilted plane (RasterizedPositionsLieWithinTheOriginPush).
    constexpr float kPushPerUnit = 1.0f / 65536.0f;
    const float magnitude = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), 1.0f});
    return o + (kPushPerUnit * magnitude) * n;
}

std::vector<std::uint8_t> lightReach(const Light& light, const std::vector<SurfaceSample>& samples) {
    const LightSetup setup = makeLightSetup(light);
    std::vector<std::uint8_t> out(samples.size(), 0);
    for (std::size_t i = 0; i < samples.size(); ++i) out[i] = setup.reaches(samples[i]) ? 1 : 0;
    return out;
}

RayTracer::RayTracer(const Scene& scene) {
    RTCDevice device = rtcNewDevice(nullptr);
    if (!device)
        throw Error(std::string("RayTracer: cannot create the Embree device (rtcNewDevice): ") +
                    errorText(rtcGetDeviceError(nullptr)));
    device_.reset(device);

    const ErrorCapture errors(device);
    auto fail = [&errors](const std::string& what) {
        std::string message = "RayTracer: " + what;
        if (!errors.text().empty()) message += ": " + errors.text();
        throw Error(message);
    };

    RTCScene rtcScene = rtcNewScene(device);
    if (!rtcScene) fail("cannot create the Embree scene");
    scene_.reset(rtcScene);
    rtcSetSceneFlags(rtcScene, RTC_SCENE_FLAG_NONE);
    // HIGH (with spatial splits) builds slower but traces faster; the
    // reference is traced many times per build.
    rtcSetSceneBuildQuality(rtcScene, RTC_BUILD_QUALITY_HIGH);

    for (const DrawItem& item : scene.drawItems()) {
        if (!item.castsShadows || item.mesh < 0) continue;
        if (static_cast<std::size_t>(item.mesh) >= scene.meshes.size())
            fail("draw item of node " + std::to_string(item.node) + " references mesh " +
                 std::to_string(item.mesh) + ", but the scene has " + std::to_string(scene.meshes.size()));
        const Mesh& mesh = scene.meshes[static_cast<std::size_t>(item.mesh)];
        const std::size_t triangles = mesh.triangleCount();
        if (triangles == 0 || mesh.positions.empty()) continue;
        for (std::size_t i = 0; i < triangles * 3; ++i)
            if (mesh.indices[i] >= mesh.positions.size())
                fail("mesh '" + mesh.name + "': index " + std::to_string(mesh.indices[i]) + " at " +
                     std::to_string(i) + " is out of range (" + std::to_string(mesh.positions.size()) +
                     " vertices)");

        RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        if (!geometry) fail("cannot create a geometry for mesh '" + mesh.name + "'");
        rtcSetGeometryBuildQuality(geometry, RTC_BUILD_QUALITY_HIGH);
        // Embree pads these buffers itself (it reads 16 bytes past the last vertex).
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.positions.size()));
        auto* indices = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), triangles));
        if (!vertices || !indices) {
            rtcReleaseGeometry(geometry);
            fail("cannot allocate the buffers of mesh '" + mesh.name + "'");
        }
        // World space: p_world = worldFromObject * (p, 1) (affine, w = 1).
        for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
            const glm::vec4 p = item.worldFromObject * glm::vec4(mesh.positions[v], 1.0f);
            vertices[3 * v + 0] = p.x;
            vertices[3 * v + 1] = p.y;
            vertices[3 * v + 2] = p.z;
        }
        std::copy_n(mesh.indices.begin(), triangles * 3, indices);
        // An alpha-tested material: a hit where its alpha is under the
        // cutoff does not occlude (the holes the GPU's alpha_test.h cuts).
        const Material* material = item.material >= 0 && static_cast<std::size_t>(item.material) < scene.materials.size()
                                       ? &scene.materials[static_cast<std::size_t>(item.material)] : nullptr;
        if (material && material->alphaTested()) {
            auto caster = std::make_unique<AlphaCaster>();
            if (mesh.uvs.size() == mesh.positions.size()) caster->uvs = mesh.uvs;
            caster->indices.assign(mesh.indices.begin(), mesh.indices.begin() + static_cast<long>(triangles * 3));
            caster->alpha = material->alpha;
            caster->cutoff = material->alphaCutoff;
            caster->translucent = material->alphaMode == AlphaMode::Blend;
            caster->baseColor = material->baseColor;
            if (material->baseColorTexture >= 0 && static_cast<std::size_t>(material->baseColorTexture) < scene.textures.size()) {
                // One copy per texture, however many casters use it.
                std::unique_ptr<ImageRGBA8>& copy = textures_[material->baseColorTexture];
                if (!copy) copy = std::make_unique<ImageRGBA8>(scene.textures[static_cast<std::size_t>(material->baseColorTexture)]);
                caster->texture = copy.get();
            }
            rtcSetGeometryUserData(geometry, caster.get());
            rtcSetGeometryOccludedFilterFunction(geometry, caster->translucent ? &translucentFilter : &alphaFilter);
            alphaCasters_.push_back(std::move(caster));
        }
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(rtcScene, geometry);
        rtcReleaseGeometry(geometry); // the scene holds its own reference
        triangleCount_ += triangles;
    }
    rtcCommitScene(rtcScene);
    if (rtcGetDeviceError(device) != RTC_ERROR_NONE || !errors.text().empty()) fail("building the BVH failed");

}

RayTracer::~RayTracer() = default;
RayTracer::RayTracer(RayTracer&&) noexcept = default;
RayTracer& RayTracer::operator=(RayTracer&&) noexcept = default;

std::size_t RayTracer::triangleCount() const { return triangleCount_; }

std::vector<float> RayTracer::visibility(const Light& light, const std::vector<SurfaceSample>& samples,
                                         const VisibilityOptions& options) const {
    if (!scene_) throw Error("RayTracer: visibility() on a moved-from tracer");
    if (options.softSamples < 1)
        throw Error("RayTracer: VisibilityOptions::softSamples must be >= 1, got " +
                    std::to_string(options.softSamples));
    const LightSetup setup = makeLightSetup(light);
    RTCScene scene = scene_.get();
    std::vector<float> result(samples.size(), 0.0f);
    // Through translucent casters the light arrives coloured: the RGB
    // transmittance per sample, when asked for; `result` is its mean.
    std::vector<glm::vec3>* colour = options.transmittance;
    if (colour) colour->assign(samples.size(), glm::vec3(0.0f));
    const auto mean = [](const glm::vec3& c) { return (c.r + c.g + c.b) / 3.0f; };

    // Ray origin: the surface point moved off its surface by an amount that
    // depends on the point alone (offsetRayOrigin), or by a fixed distance.
    const float fixedOffset = options.normalOffset;
    auto originOf = [fixedOffset](const SurfaceSample& s) {
        return fixedOffset >= 0.0f ? s.position + fixedOffset * s.normal : offsetRayOrigin(s.position, s.normal);
    };

    // Each chunk: skipped once cancelled, counted when done.
    const auto tracked = [&options](auto body) {
        return [&options, body](std::size_t begin, std::size_t end) {
            if (options.cancel && options.cancel->load(std::memory_order_relaxed)) return;
            body(begin, end);
            if (options.samplesDone) options.samplesDone->fetch_add(end - begin, std::memory_order_relaxed);
        };
    };
    const auto stopIfCancelled = [&options] {
        if (options.cancel && options.cancel->load()) throw Error("RayTracer: tracing cancelled");
    };

    if (!setup.soft) {
        // Hard: one ray per sample, 16 consecutive samples per packet (raster
        // order: neighbouring origins, parallel or converging directions).
        parallelChunks(samples.size(), 4096, tracked([&](std::size_t begin, std::size_t end) {
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
                        result[index[static_cast<std::size_t>(lane)]] = mean(t);
                        if (colour) (*colour)[index[static_cast<std::size_t>(lane)]] = t;
                    }
            }
        }));
        stopIfCancelled();
        return result;
    }

    // Soft: n rays per sample to points on the light, in packets of 16 from
    // one origin towards a small solid angle (coherent). Visibility = fraction
    // of unoccluded rays, a Monte-Carlo estimate of the visible part of the
    // light (by area for disks, by solid angle for the directional cone).
    const int n = options.softSamples;
    const int grid = static_cast<int>(std::sqrt(static_cast<double>(n))); // floor(sqrt n)
    const int stratified = grid * grid;
    const std::size_t chunk = std::max<std::size_t>(1, 65536 / static_cast<std::size_t>(n));
    parallelChunks(samples.size(), chunk, tracked([&](std::size_t begin, std::size_t end) {
        TransmitContext context;
        rtcInitIntersectContext(&context.base);
        context.base.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
        Packet packet;
        for (std::size_t i = begin; i < end; ++i) {
            const SurfaceSample& s = samples[i];
            if (!setup.reaches(s)) continue;
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
            for (int k0 = 0; k0 < n; k0 += kPacket) {
                packet.clear();
                const int count = std::min(kPacket, n - k0);
                for (int lane = 0; lane < count; ++lane) {
                    const int k = k0 + lane;
                    // Jittered grid cell (k mod g, k div g) of the unit square
                    // for the first g^2 samples, uniform for the remainder.
                    float u = rng.uniform(), v = rng.uniform();
                    if (k < stratified) {
                        u = (static_cast<float>(k % grid) + u) / static_cast<float>(grid);
                        v = (static_cast<float>(k / grid) + v) / static_cast<float>(grid);
                    }
                    float radius = 0.0f, angle = 0.0f;
                    concentricDisk(u, v, radius, angle); // uniform on the unit disk
                    const float cosA = std::cos(angle), sinA = std::sin(angle);
                    glm::vec3 dir;
                    float tfar = 0.0f;
                    if (setup.type == LightType::Directional) {
                        // Uniform in solid angle on the cap of half angle a:
                        // 1 - cos(theta) = r^2 (1 - cos a) maps disk area to cap area.
                        const float h = radius * radius * setup.oneMinusCosHalf; // 1 - cos(theta)
                        const float sinTheta = std::sqrt(std::max(0.0f, h * (2.0f - h)));
                        dir = (1.0f - h) * setup.towardLight +
                              sinTheta * (cosA * setup.coneT + sinA * setup.coneB);
                        tfar = std::numeric_limits<float>::infinity();
                    } else {
                        const glm::vec3 target =
                            setup.position + setup.size * radius * (cosA * diskT + sinA * diskB);
                        if (!rayToPoint(o, target, dir, tfar)) {
                            unoccluded += glm::vec3(1.0f); // on the light itself
                            continue;
                        }
                    }
                    packet.set(lane, o, dir, tfar);
                }
                context.reset();
                packet.trace(scene, context.base);
                for (int lane = 0; lane < count; ++lane)
                    if (packet.valid[static_cast<std::size_t>(lane)] && !packet.occluded(lane)) unoccluded += context.transmit[static_cast<std::size_t>(lane)];
            }
            const glm::vec3 t = unoccluded / static_cast<float>(n);
            result[i] = mean(t);
            if (colour) (*colour)[i] = t;
        }
    }));
    stopIfCancelled();
    return result;
}

} // namespace shadowlab::reference
