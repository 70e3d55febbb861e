#version 330 core
// 08 - The Shadow Map, shadow pass (seed 001): render every caster's depth from the light.
// The deferred scene (seed 000) uses it too: its shadow_vs / shadow_fs are the same.
uniform mat4 u_light_vp;
uniform mat4 u_model;
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;

void main() {
    gl_Position = u_light_vp * u_model * vec4(a_pos, 1.0);
}
