#pragma once
// Cascaded shadow maps of a directional light (Cascades.cpp): the view's
// depth range in slices, where the receivers the view sees start and end,
// and each slice's light camera, tight or stabilised.
#include "geometry/LightCamera.h"

#include <glm/glm.hpp>

#include <vector>

namespace shadowlab {

/// Cascaded shadow maps (directional lights): the view's depth range
/// [near, far] split into `count` slices, each slice's far distance along
/// the view axis (the last is `far`). With `given` (count - 1 increasing
/// distances) those, else the practical scheme (Zhang et al. 2006): lambda x
/// the logarithmic split + (1 - lambda) x the uniform one.
std::vector<float> cascadeSplits(float near, float far, int count, float lambda, const std::vector<float>& given = {});

/// How far along the view axis receivers the camera sees reach: the
/// farthest corner of their bounds within the frustum, at most the camera's
/// far plane and at least just past its near one.
float viewReach(const Camera& camera, const FitInput& in);
/// Stabilised cascades: the box of every receiver (the scene's, fixed as
/// the camera moves) in light view `lightView`, cut across the light to
/// the box of the casters that can shadow one (a plane with every receiver
/// on its lit side cannot): per axis its half width times `grow` (the
/// filter's padding) rounded up to a power of 2^(1/8), so that items that
/// move change it by steps (xy), and its centre (zw); all 0 without
/// receivers or casters over them. fitCascade (and the GPU's fit) take it
/// as the window on an axis where it is narrower than the slice's sphere.
glm::vec4 receiversWindow(const FitInput& in, const glm::mat4& lightView, float grow);
/// The nearest view depth (along the view, scene units) of the receivers'
/// boxes that may be in view: where the receivers the camera sees may
/// start, never farther than the nearest of them (a box reaching behind
/// the near plane gives the near plane); the far plane when none is in
/// view. Not the nearest point of a box inside the view's pyramid: a
/// ground under the camera then starts metres out, and splits placed from
/// there moved every slice out (cascades-field's p95 texel footprint 17.3
/// -> 22.2 pixels a texel, long-view's 4.0 -> 6.7).
float viewNearest(const Camera& camera, const FitInput& in);

/// One cascade: an orthographic light camera for the slice [near, far] of
/// `camera`'s view (aspect: width / height) along `direction`.
/// Tight (stabilize false): fitDirectional() for the receivers and casters
/// of that slice. Stabilised: the slice's bounding sphere (its radius does
/// not change as the camera moves or turns), a light view of fixed
/// orientation and origin, the box's centre snapped to whole texels and its
/// depth over the whole scene, so the map's texel grid stays put in the world
/// while the camera moves (no shimmer).
/// `readFrom` (stabilised): a depth along the view no farther than the
/// nearest whose lookups read this cascade (at most `near`, 0: `near`): the
/// map's depth range holds what the view's frustum holds from it to `far`.
/// `castsFrom` (stabilised; 0: readFrom): the nearest depth whose lookups
/// read this cascade (the previous slice's blend zone), no nearer than
/// readFrom: only casters that can shadow a receiver seen between it and
/// `far` are kept in `casts` (castersOverSlice).
/// `warp` (tight cascades only, stabilize false): each slice's map warped
/// as fitDirectional warps one.
/// Stabilised, `lookups` holds the receivers seen between castsFrom and `far`.
LightCamera fitCascade(const glm::vec3& direction, const Camera& camera, float aspect, float near, float far, bool stabilize, const FitInput& in,
                       float readFrom = 0.0f, const LightWarp* warp = nullptr, float castsFrom = 0.0f);

} // namespace shadowlab
