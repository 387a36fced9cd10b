/// @file RayTracerBuild.cpp
/// The tracer's BVH: an Embree device and scene holding every shadow-casting
/// DrawItem in world space, with an occlusion filter on each alpha-tested or
/// translucent caster (AlphaCaster.h); the Embree errors raised while it is
/// built name what failed.
#include "reference/RayTracer.h"

#include "reference/AlphaCaster.h"

#include <shadowlab/Error.h>

#include <embree3/rtcore.h>

#include <algorithm>
#include <string>

namespace shadowlab::reference {

void RayTracer::DeviceDeleter::operator()(RTCDeviceTy* device) const { rtcReleaseDevice(device); }
void RayTracer::SceneDeleter::operator()(RTCSceneTy* scene) const { rtcReleaseScene(scene); }

namespace {

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

    // Throws shadowlab::Error "RayTracer: <what>", followed by the errors
    // collected so far, if any.
    [[noreturn]] void fail(const std::string& what) const {
        std::string message = "RayTracer: " + what;
        if (!text().empty()) message += ": " + text();
        throw Error(message);
    }

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

// Fails unless each of the mesh's first `triangles` * 3 indices names one of
// its vertices.
void checkIndices(const Mesh& mesh, std::size_t triangles, const ErrorCapture& errors) {
    for (std::size_t i = 0; i < triangles * 3; ++i)
        if (mesh.indices[i] >= mesh.positions.size())
            errors.fail("mesh '" + mesh.name + "': index " + std::to_string(mesh.indices[i]) + " at " +
                        std::to_string(i) + " is out of range (" + std::to_string(mesh.positions.size()) +
                        " vertices)");
}

// A triangle geometry of the item's mesh, its vertices in world space, not
// yet committed.
RTCGeometry newTriangleGeometry(RTCDevice device, const DrawItem& item, const Mesh& mesh, std::size_t triangles,
                                const ErrorCapture& errors) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (!geometry) errors.fail("cannot create a geometry for mesh '" + mesh.name + "'");
    rtcSetGeometryBuildQuality(geometry, RTC_BUILD_QUALITY_HIGH);
    // Embree pads these buffers itself (it reads 16 bytes past the last vertex).
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.positions.size()));
    auto* indices = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), triangles));
    if (!vertices || !indices) {
        rtcReleaseGeometry(geometry);
        errors.fail("cannot allocate the buffers of mesh '" + mesh.name + "'");
    }
    // World space: p_world = worldFromObject * (p, 1) (affine, w = 1).
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::vec4 p = item.worldFromObject * glm::vec4(mesh.positions[v], 1.0f);
        vertices[3 * v + 0] = p.x;
        vertices[3 * v + 1] = p.y;
        vertices[3 * v + 2] = p.z;
    }
    std::copy_n(mesh.indices.begin(), triangles * 3, indices);
    return geometry;
}

// What the occlusion filter of a caster with an alpha-tested `material`
// reads; its base-colour texture is the tracer's copy in `textures`.
std::unique_ptr<RayTracer::AlphaCaster> makeAlphaCaster(const Scene& scene, const Mesh& mesh, std::size_t triangles,
                                                        const Material* material,
                                                        std::map<int, std::unique_ptr<ImageRGBA8>>& textures) {
    auto caster = std::make_unique<RayTracer::AlphaCaster>();
    if (mesh.uvs.size() == mesh.positions.size()) caster->uvs = mesh.uvs;
    caster->indices.assign(mesh.indices.begin(), mesh.indices.begin() + static_cast<long>(triangles * 3));
    caster->alpha = material->alpha;
    caster->cutoff = material->alphaCutoff;
    caster->translucent = material->alphaMode == AlphaMode::Blend;
    caster->baseColor = material->baseColor;
    if (material->baseColorTexture >= 0 && static_cast<std::size_t>(material->baseColorTexture) < scene.textures.size()) {
        // One copy per texture, however many casters use it.
        std::unique_ptr<ImageRGBA8>& copy = textures[material->baseColorTexture];
        if (!copy) copy = std::make_unique<ImageRGBA8>(scene.textures[static_cast<std::size_t>(material->baseColorTexture)]);
        caster->texture = copy.get();
    }
    return caster;
}

} // namespace

RayTracer::RayTracer(const Scene& scene) {
    RTCDevice device = rtcNewDevice(nullptr);
    if (!device)
        throw Error(std::string("RayTracer: cannot create the Embree device (rtcNewDevice): ") +
                    errorText(rtcGetDeviceError(nullptr)));
    device_.reset(device);

    const ErrorCapture errors(device);

    RTCScene rtcScene = rtcNewScene(device);
    if (!rtcScene) errors.fail("cannot create the Embree scene");
    scene_.reset(rtcScene);
    rtcSetSceneFlags(rtcScene, RTC_SCENE_FLAG_NONE);
    // HIGH (with spatial splits) builds slower but traces faster; the
    // reference is traced many times per build.
    rtcSetSceneBuildQuality(rtcScene, RTC_BUILD_QUALITY_HIGH);

    for (const DrawItem& item : scene.drawItems()) {
        if (!item.castsShadows || item.mesh < 0) continue;
        if (static_cast<std::size_t>(item.mesh) >= scene.meshes.size())
            errors.fail("draw item of node " + std::to_string(item.node) + " references mesh " +
                        std::to_string(item.mesh) + ", but the scene has " + std::to_string(scene.meshes.size()));
        const Mesh& mesh = scene.meshes[static_cast<std::size_t>(item.mesh)];
        const std::size_t triangles = mesh.triangleCount();
        if (triangles == 0 || mesh.positions.empty()) continue;
        checkIndices(mesh, triangles, errors);

        RTCGeometry geometry = newTriangleGeometry(device, item, mesh, triangles, errors);
        // An alpha-tested material: a hit where its alpha is under the
        // cutoff does not occlude (the holes the GPU's alpha_test.h cuts).
        const Material* material = item.material >= 0 && static_cast<std::size_t>(item.material) < scene.materials.size()
                                       ? &scene.materials[static_cast<std::size_t>(item.material)] : nullptr;
        if (material && material->alphaTested()) {
            auto caster = makeAlphaCaster(scene, mesh, triangles, material, textures_);
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
    if (rtcGetDeviceError(device) != RTC_ERROR_NONE || !errors.text().empty()) errors.fail("building the BVH failed");
}

RayTracer::~RayTracer() = default;
RayTracer::RayTracer(RayTracer&&) noexcept = default;
RayTracer& RayTracer::operator=(RayTracer&&) noexcept = default;

std::size_t RayTracer::triangleCount() const { return triangleCount_; }

} // namespace shadowlab::reference
