// Wood: rings around the object's y axis, their radius disturbed by value
// noise, and a fine grain along the axis.
uniform float ring_scale;
varying vec3 object_position;
varying vec3 normal, position;
void main() {
    object_position = gl_Vertex.xyz;
    position = vec3(gl_ModelViewMatrix * gl_Vertex);
    normal = gl_NormalMatrix * gl_Normal;
    gl_Position = ftransform();
}
