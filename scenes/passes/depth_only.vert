// The shadow pass: depth only, from the light (the pass's camera).
void main() { gl_Position = ftransform(); }
