/// @file AlphaCaster.cpp
/// Embree's occlusion filters for alpha-tested casters (a hit in a hole is
/// rejected) and translucent ones (the ray goes on, filtered by the
/// surface's transmittance), installed by the tracer's build.
#include "reference/AlphaCaster.h"

#include <algorithm>

namespace shadowlab::reference {

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

void alphaFilter(const RTCFilterFunctionNArguments* args) {
    const auto* caster = static_cast<const RayTracer::AlphaCaster*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
        if (!caster->solidAt(prim, RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i))) args->valid[i] = 0;
    }
}

} // namespace shadowlab::reference
