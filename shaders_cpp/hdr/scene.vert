#version 330 core
// 11 - HDR + Bloom, pass 1 (seed 002, scene_vs): the instanced cube swarm. Per instance
// the cube breathes and spins about Y, desynchronised by its phase.
// per-vertex (binding 0): pos + normal
layout(location = 0) in vec3 a_pos;
layout(location = 1) in vec3 a_normal;
// per-instance (binding 1): offset + colour + phase + emissive flag (1 = glows)
layout(location = 2) in vec3 a_offset;
layout(location = 3) in vec3 a_color;
layout(location = 4) in float a_phase;
layout(location = 5) in float a_emissive;
uniform mat4 u_view;
uniform mat4 u_proj;
uniform float u_time;
out vec3 w_pos;
out vec3 w_normal;
out vec3 w_color;
out float w_emissive;

void main() {
    float t = u_time;
    // per-instance breathing + gentle spin about Y, desynchronised by the phase
    float breathe = 0.7 + 0.2 * sin(t * 1.5 + a_phase * 6.2832);
    vec3 local = a_pos * breathe;
    float ang = t * 0.25 + a_phase * 6.2832;
    float c = cos(ang);
    float s = sin(ang);
    vec3 rotated = vec3(c * local.x - s * local.z, local.y, s * local.x + c * local.z);
    vec3 world = rotated + a_offset;
    gl_Position = u_proj * u_view * vec4(world, 1.0);
    w_pos = world;
    w_normal = vec3(c * a_normal.x - s * a_normal.z, a_normal.y, s * a_normal.x + c * a_normal.z);
    w_color = a_color;
    w_emissive = a_emissive;
}
