using System;

namespace GregoryTerrain
{
    /// <summary>
    /// A 4x4 float matrix stored as four columns, used with column vectors (<c>clip = M * p</c>), the
    /// convention of Unity's <c>Matrix4x4</c> and of HLSL's <c>mul(M, v)</c> in Unity shaders.
    /// </summary>
    internal struct Float4x4 : IEquatable<Float4x4>
    {
        public Float4 c0, c1, c2, c3;

        public Float4x4(Float4 c0, Float4 c1, Float4 c2, Float4 c3) { this.c0 = c0; this.c1 = c1; this.c2 = c2; this.c3 = c3; }

        public static readonly Float4x4 identity = new Float4x4(
            new Float4(1f, 0f, 0f, 0f), new Float4(0f, 1f, 0f, 0f), new Float4(0f, 0f, 1f, 0f), new Float4(0f, 0f, 0f, 1f));

        /// <summary>Builds a matrix from its rows as written on paper: <c>mRC</c> is row R, column C.</summary>
        public static Float4x4 FromRows(
            float m00, float m01, float m02, float m03,
            float m10, float m11, float m12, float m13,
            float m20, float m21, float m22, float m23,
            float m30, float m31, float m32, float m33) => new Float4x4(
            new Float4(m00, m10, m20, m30), new Float4(m01, m11, m21, m31),
            new Float4(m02, m12, m22, m32), new Float4(m03, m13, m23, m33));

        /// <summary><c>M * v</c>, summed column by column in a fixed order (so results are reproducible).</summary>
        public static Float4 operator *(Float4x4 m, Float4 v) => m.c0 * v.x + m.c1 * v.y + m.c2 * v.z + m.c3 * v.w;

        /// <summary>Transforms a point (w = 1).</summary>
        public Float4 TransformPoint(Float3 p) => this * new Float4(p, 1f);

        public bool IsFinite => c0.IsFinite && c1.IsFinite && c2.IsFinite && c3.IsFinite;

        public bool Equals(Float4x4 o) => c0.Equals(o.c0) && c1.Equals(o.c1) && c2.Equals(o.c2) && c3.Equals(o.c3);
        public override bool Equals(object obj) => obj is Float4x4 o && Equals(o);
        public override int GetHashCode() => HashCode.Combine(c0, c1, c2, c3);
        public override string ToString() => FormattableString.Invariant($"[{c0}, {c1}, {c2}, {c3}]");
    }
}
