// Technique "map", filter "pcf20": the lecture's 20 offset directions
// (001) times the radius, far apart, none along the ray. Cube maps only.
#if !MAP_CUBE
#error filter pcf20 is for point lights' cube maps
#endif
const vec3 kPcf20[20] = vec3[](
    vec3(1, 1, 1), vec3(1, -1, 1), vec3(-1, -1, 1), vec3(-1, 1, 1),
    vec3(1, 1, -1), vec3(1, -1, -1), vec3(-1, -1, -1), vec3(-1, 1, -1),
    vec3(1, 1, 0), vec3(1, -1, 0), vec3(-1, -1, 0), vec3(-1, 1, 0),
    vec3(1, 0, 1), vec3(-1, 0, 1), vec3(1, 0, -1), vec3(-1, 0, -1),
    vec3(0, 1, 1), vec3(0, -1, 1), vec3(0, -1, -1), vec3(0, 1, -1));

float cubeReach(float texel, float radius) { return radius * 1.7320508; }  // |(1, 1, 1)| x radius

float cubeFilter(vec3 v, float ref, vec3 n, float radius) {
    float sum = 0.0;
    for (int k = 0; k < 20; ++k) sum += cubeTap(v + kPcf20[k] * radius, ref);
    return sum / 20.0;
}
