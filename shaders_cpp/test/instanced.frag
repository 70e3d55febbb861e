#version 330 core
// Test program: writes the interpolated colour (the instance number in alpha).
in vec4 v_color;
layout(location = 0) out vec4 f_color;

void main() {
    f_color = v_color;
}
