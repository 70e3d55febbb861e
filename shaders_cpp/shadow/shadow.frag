#version 330 core
// 08 - The Shadow Map, shadow pass: depth-only framebuffer, this colour is discarded.
layout(location = 0) out vec4 f_FragColor;

void main() {
    f_FragColor = vec4(1.0, 1.0, 1.0, 1.0);
}
