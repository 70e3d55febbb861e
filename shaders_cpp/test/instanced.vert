#version 330 core
// Test program: instanced draws. Per vertex a clip position and a colour (buffer 0); per
// instance (divisor 1, buffer 1) an offset added to the position and a colour multiplied in;
// gl_InstanceID goes to alpha so each instance's pixels name it.
layout(location = 0) in vec4 a_pos;
layout(location = 1) in vec4 a_color;
layout(location = 2) in vec3 i_offset;
layout(location = 3) in vec4 i_color;
out vec4 v_color;

void main() {
    v_color = vec4(a_color.rgb * i_color.rgb, float(gl_InstanceID));
    gl_Position = vec4(a_pos.xyz + i_offset, a_pos.w);
}
