uniform samplerCube environment;
varying vec3 direction;
void main() { gl_FragColor = textureCube(environment, direction); }
