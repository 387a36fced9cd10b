// Technique "none": every point is lit. The unshadowed baseline.
vec3 shadowVisibility(vec3 worldPosition, vec3 worldNormal) {
    return vec3(1.0);
}
