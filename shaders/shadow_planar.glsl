// Technique "planar": the shadow is in the stencil (src/techniques/
// Planar.cpp), so the light pass adds the light only where it is not
// marked; the visibility term itself is 1.
vec3 shadowVisibility(vec3 worldPosition, vec3 worldNormal) {
    return vec3(1.0);
}
