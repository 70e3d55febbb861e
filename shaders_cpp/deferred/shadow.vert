#version 330 core
// 10 - Deferred Shading + MRT (seed 000), shadow pass: depth-only from the sun's POV.
uniform mat4 u_light_vp;
uniform mat4 u_model;
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;

void main() {
    gl_Position = u_light_vp * u_model * vec4(a_pos, 1.0);
}
