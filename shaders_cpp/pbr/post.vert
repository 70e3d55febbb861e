#version 330 core
// PBR, fullscreen passes (SSAO, blur, lighting): the seed's one triangle over the screen,
// (-1, -1), (3, -1), (-1, 3), clipped to the viewport.
layout(location = 0) in vec2 aPos;
out vec2 fragUV;

void main() {
    gl_Position = vec4(aPos, 0.0, 1.0);
    fragUV = aPos * 0.5 + 0.5;
}
