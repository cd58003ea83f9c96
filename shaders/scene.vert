// The GLSL path of the viewing pipeline (docs/conventions.md, "The GLSL path with the same matrices"):
// the CPU pipeline's own matrices, column vectors, applied right to left:
//   gl_Position = glClipFromNpc · npcFromVrc · vrcFromWc · wcFromMc · p
// No other projection matrix exists. glClipFromNpc takes the NPC cube (front z = w) to GL's clip
// volume (near plane z = −w) without changing what is inside, so GL's clipper clips to the cube.
// No #version line: the loader (app/gl/shader.cpp) puts "#version 330 core" or "#version 300 es" first.
precision highp float;

layout(location = 0) in vec3 mcPosition;  // MC
layout(location = 1) in vec3 mcNormal;    // MC

uniform mat4 wcFromMc;          // stage 1
uniform mat4 vrcFromWc;         // stage 2, of the camera this view is seen through
uniform mat4 npcFromVrc;        // stage 3
uniform mat4 glClipFromNpc;     // the constant of docs/conventions.md
uniform mat3 wcNormalFromMc;    // inverse transpose of wcFromMc's 3 × 3 (lecture notes 13.5)

// Another camera's view volume (the world view shows the scene camera's volume solid and the rest
// faded): that camera's homogeneous NPC, whose boundary coordinates the fragment shader tests.
uniform mat4 volumeNpcFromWc;
// User clip planes in WC (DGL wiki, glClipPlane): a·x + b·y + c·z + d ≥ 0 is kept.
uniform int userPlaneCount;
uniform vec4 userPlanesWc[6];

out vec3 wcPosition;
out vec3 wcNormal;
out vec4 volumeNpcH;
#ifdef USER_PLANES  // only in the program for scenes with user planes: costly when written
#ifdef GL_ES  // GLSL ES 3.00 has no gl_ClipDistance: scene.frag discards where a distance is negative
out float gClipDistance[6];
#else
out float gl_ClipDistance[6];
#endif
#endif

void main() {
  vec4 wc = wcFromMc * vec4(mcPosition, 1.0);
  wcPosition = wc.xyz;
#ifdef FACE_NORMAL
  wcNormal = vec3(0.0);  // the fragment shader takes the plane's
#else
  wcNormal = wcNormalFromMc * mcNormal;
#endif

  volumeNpcH = volumeNpcFromWc * wc;
#ifdef USER_PLANES
  for (int i = 0; i < 6; ++i) {
#ifdef GL_ES
    gClipDistance[i] = i < userPlaneCount ? dot(userPlanesWc[i], wc) : 1.0;
#else
    gl_ClipDistance[i] = i < userPlaneCount ? dot(userPlanesWc[i], wc) : 1.0;
#endif
  }
#endif

  gl_Position = glClipFromNpc * npcFromVrc * vrcFromWc * wc;
}
