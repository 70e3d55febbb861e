#version 330 core
// Deferred, fullscreen passes (SSAO and lighting share it): one triangle over the screen.
layout(location = 0) in vec2 q_pos;
out vec2 l_uv;

void main() {
    gl_Position = vec4(q_pos, 0.0, 1.0);
    l_uv = q_pos * 0.5 + vec2(0.5, 0.5);
}
