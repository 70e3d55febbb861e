#version 330 core
// 08 - The Shadow Map, main pass (seed 001): world position and normal for lighting, and the
// position projected into light space (pre-divide) for the shadow lookup.
uniform mat4 u_light_vp;
uniform mat4 u_model;
uniform mat4 u_view;
uniform mat4 u_proj;
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
out vec3 v_world_pos;
out vec3 v_world_normal;
out vec4 v_light_space;

void main() {
    vec4 world = u_model * vec4(a_pos, 1.0);
    v_world_pos = world.xyz;
    // model is rotation + uniform scale only, so a (normal, 0) multiply is correct
    v_world_normal = (u_model * vec4(a_normal, 0.0)).xyz;
    v_light_space = u_light_vp * world;
    gl_Position = u_proj * u_view * world;
}
