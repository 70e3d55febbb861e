#version 330 core
// Test program: one shadow-map lookup (2x2 compare, LEQUAL) written to an RGBA16F target.
uniform sampler2DShadow shadow_map;
in vec4 v_lookup;
layout(location = 0) out vec4 f_result;

void main() {
    f_result = vec4(texture(shadow_map, vec3(v_lookup.xy, v_lookup.z)), 0.0, 0.0, 1.0);
}
