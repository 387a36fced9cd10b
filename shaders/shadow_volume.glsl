// Technique "volume": the shadow is in the stencil (src/techniques/
// Volume.cpp), so the light pass adds the light only where the count is 0;
// the visibility term itself is 1.
vec3 shadowVisibility(vec3 worldPosition, vec3 worldNormal) {
    return vec3(1.0);
}
