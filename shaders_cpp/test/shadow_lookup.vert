#version 330 core
// Test program: clip-space positions; a (u, v, ref, 0) lookup passed through as a varying.
layout(location = 0) in vec4 a_pos;
layout(location = 1) in vec4 a_lookup;
out vec4 v_lookup;

void main() {
    v_lookup = a_lookup;
    gl_Position = a_pos;
}
