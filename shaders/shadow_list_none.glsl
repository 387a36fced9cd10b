// The light list's shadow lookup when no listed light has a shadow
// (lighting.frag's "@list_shadow" slot; LIGHT_LIST_SHADOWS is 0 then and
// this is never called).
float listedVisibility(vec4 shadow, vec3 lightPosition, vec3 p, vec3 n, vec3 L, float NdotL) { return 1.0; }
