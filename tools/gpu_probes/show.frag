// A render target's texels on the screen, unfiltered where the screen has the
// target's size (uv at texel centres): shows one stage of a post-process chain.
uniform sampler2D image;
varying vec2 uv;

void main()
{
    gl_FragColor = texture2D(image, uv);
}
