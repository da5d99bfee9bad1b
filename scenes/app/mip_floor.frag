uniform sampler2D floor_texture;
void main() { gl_FragColor = gl_Color * texture2D(floor_texture, gl_TexCoord[0].st); }
