using System;

namespace GregoryTerrain
{
    /// <summary>Three floats, the GPU's float3: the arithmetic the shaders do.</summary>
    [Serializable]
    public struct Float3 : IEquatable<Float3>
    {
        public float x, y, z;

        public Float3(float x, float y, float z) { this.x = x; this.y = y; this.z = z; }

        public static readonly Float3 zero = default;

        public static Float3 operator +(Float3 a, Float3 b) => new Float3(a.x + b.x, a.y + b.y, a.z + b.z);
        public static Float3 operator -(Float3 a, Float3 b) => new Float3(a.x - b.x, a.y - b.y, a.z - b.z);
        public static Float3 operator -(Float3 a) => new Float3(-a.x, -a.y, -a.z);
        public static Float3 operator *(Float3 a, float s) => new Float3(a.x * s, a.y * s, a.z * s);
        public static Float3 operator *(float s, Float3 a) => new Float3(a.x * s, a.y * s, a.z * s);
        public static Float3 operator /(Float3 a, float s) => new Float3(a.x / s, a.y / s, a.z / s);

        /// <summary>Rounds a double vector to float per component, as an upload to the GPU does.</summary>
        public static explicit operator Float3(Double3 d) => new Float3((float)d.x, (float)d.y, (float)d.z);

        public bool IsFinite => GMath.isfinite(x) && GMath.isfinite(y) && GMath.isfinite(z);

        public bool Equals(Float3 o) => x.Equals(o.x) && y.Equals(o.y) && z.Equals(o.z);
        public override bool Equals(object obj) => obj is Float3 o && Equals(o);
        public override int GetHashCode() => HashCode.Combine(x, y, z);
        public override string ToString() => FormattableString.Invariant($"({x:R}, {y:R}, {z:R})");
    }
}
