#version 330 core
// Test program: positions are already in clip space; one vec4 varying for the derivatives.
layout(location = 0) in vec4 a_pos;
layout(location = 1) in vec4 a_value;
out vec4 v_value;

void main() {
    v_value = a_value;
    gl_Position = a_pos;
}
