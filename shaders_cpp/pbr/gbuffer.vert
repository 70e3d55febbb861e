#version 330 core
// PBR, geometry pass (seed 004, "Deferred shading"): world position, normal and uv for the
// G-buffer.
uniform mat4 u_model;
uniform mat4 u_view;
uniform mat4 u_proj;
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;
out vec3 fragPos;
out vec3 fragNormal;
out vec2 fragUV;

void main() {
    vec4 world = u_model * vec4(a_pos, 1.0);
    fragPos = world.xyz;
    fragNormal = normalize((u_model * vec4(a_normal, 0.0)).xyz);
    fragUV = a_uv;
    gl_Position = u_proj * u_view * world;
}
