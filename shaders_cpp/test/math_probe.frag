#version 330 core
// Test program: one GLSL built-in, picked by u_func, on arguments x and y, into an RGBA32F
// target as (f(x, y), x, y, 0). An argument is (value * scale) * scale2: the scales are 1
// except to make +-Inf (3e38 * 2) and NaN (Inf * 0), which no interpolated varying can
// carry. Literal exponents stay literals, so the compiler folds them as in any shader.
uniform int u_func;
in vec4 v_x;
in vec4 v_y;
layout(location = 0) out vec4 f_result;

void main() {
    float x = (v_x.x * v_x.y) * v_x.z;
    float y = (v_y.x * v_y.y) * v_y.z;
    float r = 0.0;
    if (u_func == 0) r = exp2(x);
    else if (u_func == 1) r = log2(x);
    else if (u_func == 2) r = pow(x, y);
    else if (u_func == 3) r = pow(x, 48.0);
    else if (u_func == 4) r = pow(x, 2.2);
    else if (u_func == 5) r = pow(x, 0.4545);
    else if (u_func == 6) r = pow(x, 2.0);
    else if (u_func == 7) r = pow(x, 4.0);
    else if (u_func == 8) r = sin(x);
    else if (u_func == 9) r = cos(x);
    else if (u_func == 10) r = atan(x, y);
    else if (u_func == 11) r = acos(x);
    else if (u_func == 12) r = asin(x);
    else if (u_func == 13) r = atan(x);
    else if (u_func == 14) r = pow(vec3(x, y, x), vec3(2.2)).y;
    else if (u_func == 15) r = pow(vec3(x, x, x), vec3(y, 0.4545, 2.0)).x;
    f_result = vec4(r, x, y, 0.0);
}
