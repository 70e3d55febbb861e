#version 330 core
// PBR, SSAO blur (seed 004: "a separable Gaussian blur ... horizontally then vertically in
// two passes"): a 9-tap Gaussian along uDirection, one texel step along x, then along y.
uniform sampler2D uInput;
uniform vec2 uDirection;
in vec2 fragUV;
layout(location = 0) out vec4 fragColor;

const float WEIGHTS[5] = float[](0.227027, 0.1945946, 0.1216216, 0.054054, 0.016216);

void main() {
    float result = texture(uInput, fragUV).r * WEIGHTS[0];
    for (int i = 1; i < 5; ++i) {
        result += texture(uInput, fragUV + uDirection * float(i)).r * WEIGHTS[i];
        result += texture(uInput, fragUV - uDirection * float(i)).r * WEIGHTS[i];
    }
    fragColor = vec4(vec3(result), 1.0);
}
