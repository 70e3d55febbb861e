#version 330 core
// Test program: one element of each of three uniform arrays (vec3, float, mat4) per output
// channel, with no arithmetic, so an element set by its name "uVectors[i]" shows in the bits.
uniform vec3 uVectors[3];
uniform float uScalars[2];
uniform mat4 uMatrices[2];
in vec4 v_color;
layout(location = 0) out vec4 f_vectors;
layout(location = 1) out vec4 f_scalars;

void main() {
    f_vectors = vec4(uVectors[0].x, uVectors[1].y, uVectors[2].z, v_color.a);
    f_scalars = vec4(uScalars[0], uScalars[1], uMatrices[0][1].y, uMatrices[1][3].x);
}
