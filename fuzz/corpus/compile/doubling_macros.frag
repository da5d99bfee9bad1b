#define A1 x+x
#define A2 A1+A1
#define A3 A2+A2
#define A4 A3+A3
#define A5 A4+A4
#define A6 A5+A5
#define F(a) a*a
uniform float x;
void main() { gl_FragColor = vec4(F(F(A6))); }
