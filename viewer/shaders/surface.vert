#version 330 core
// Per-vertex position, normal and RGBA colour, in the shape's coordinates;
// Qt3D supplies the matrices.
in vec3 vertexPosition;
in vec3 vertexNormal;
in vec4 vertexColor;
in vec2 vertexTexCoord;

out vec3 worldPosition;
out vec3 worldNormal;
out vec4 colour;
out vec2 texCoord;

uniform mat4 modelMatrix;
uniform mat3 modelNormalMatrix;
uniform mat4 mvp;
uniform float pointSize;

void main()
{
    worldPosition = (modelMatrix * vec4(vertexPosition, 1.0)).xyz;
    worldNormal = modelNormalMatrix * vertexNormal;
    colour = vertexColor;
    texCoord = vertexTexCoord;
    gl_PointSize = pointSize;
    gl_Position = mvp * vec4(vertexPosition, 1.0);
}
