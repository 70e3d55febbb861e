#version 330 core
// Test program: clip-space positions; two arguments carried as (value, scale, scale2, 0).
layout(location = 0) in vec4 a_pos;
layout(location = 1) in vec4 a_x;
layout(location = 2) in vec4 a_y;
out vec4 v_x;
out vec4 v_y;

void main() {
    v_x = a_x;
    v_y = a_y;
    gl_Position = a_pos;
}
