#version 330 core
// Test program: one sampler2D lookup per fragment at an interpolated (u, v).
layout(location = 0) in vec4 a_pos;
layout(location = 1) in vec4 a_lookup;
out vec4 v_lookup;

void main() {
    v_lookup = a_lookup;
    gl_Position = a_pos;
}
