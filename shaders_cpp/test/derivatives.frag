#version 330 core
// Test program: fine derivatives of non-linear functions of a varying (RGBA16F target).
// q is written factored: Mesa's NIR rewrites a*b + a*c into a*(b + c) (nir_opt_algebraic),
// so x*x*y + y*0.25 would be compiled as this anyway.
in vec4 v_value;
layout(location = 0) out vec4 f_derivatives;

void main() {
    float q = v_value.y * (v_value.x * v_value.x + 0.25);
    float p = v_value.x * v_value.y;
    f_derivatives = vec4(dFdx(q), dFdy(q), dFdx(p), dFdy(p * v_value.z));
}
