#version 330 core
// Test program: writes an RGBA8 colour, a signed HDR value and a world-position-like value.
in vec4 v_color;
layout(location = 0) out vec4 out_unorm;
layout(location = 1) out vec4 out_signed;
layout(location = 2) out vec4 out_large;

void main() {
    out_unorm = v_color;
    out_signed = v_color * 2.0 - vec4(1.0, 1.0, 1.0, 1.0);
    out_large = v_color * 300.0;
}
