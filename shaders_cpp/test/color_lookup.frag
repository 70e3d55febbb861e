#version 330 core
// Test program: writes texture(tex, uv) (to an RGBA32F target, so the result is exact).
uniform sampler2D tex;
in vec4 v_lookup;
layout(location = 0) out vec4 f_color;

void main() {
    f_color = texture(tex, v_lookup.xy);
}
