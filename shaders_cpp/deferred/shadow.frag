#version 330 core
// Deferred, shadow pass: depth-only framebuffer (colour draw buffer is GL_NONE) -- discarded.
layout(location = 0) out vec4 g_albedo_out;

void main() {
    g_albedo_out = vec4(1.0, 1.0, 1.0, 1.0);
}
