using UnityEngine;

namespace GregoryTerrain
{
    /// <summary>Core's vectors and matrices to Unity's and back, and the object -> clip transform the stages get.</summary>
    static class UnityConversions
    {
        public static Vector4 ToVector(Float4 v) => new Vector4(v.x, v.y, v.z, v.w);

        public static Float4x4 ToFloat4x4(Matrix4x4 m) => Float4x4.FromRows(
            m.m00, m.m01, m.m02, m.m03, m.m10, m.m11, m.m12, m.m13,
            m.m20, m.m21, m.m22, m.m23, m.m30, m.m31, m.m32, m.m33);

        public static Matrix4x4 ToMatrix4x4(Float4x4 f) => new Matrix4x4
        {
            m00 = f.c0.x, m10 = f.c0.y, m20 = f.c0.z, m30 = f.c0.w,
            m01 = f.c1.x, m11 = f.c1.y, m21 = f.c1.z, m31 = f.c1.w,
            m02 = f.c2.x, m12 = f.c2.y, m22 = f.c2.z, m32 = f.c2.w,
            m03 = f.c3.x, m13 = f.c3.y, m23 = f.c3.z, m33 = f.c3.w,
        };

        /// <summary>
        /// The terrain's object -> clip transform as the graphics stages get it (GT_ObjectToClip: the
        /// platform's depth range and orientation). A render-texture y flip changes no factor (screen
        /// lengths) nor the culling (symmetric in y): renderIntoTexture = false serves every target.
        /// </summary>
        public static Matrix4x4 ObjectToClip(Camera cam, Float4x4 objectToWorld) =>
            GL.GetGPUProjectionMatrix(cam.projectionMatrix, false) * cam.worldToCameraMatrix * ToMatrix4x4(objectToWorld);
    }
}
