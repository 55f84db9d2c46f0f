using System;

namespace GregoryTerrain
{
    /// <summary>Three floats, the GPU's float3: the arithmetic the shaders do.</summary>
    [Serializable]
    public struct Float3 : IEquatable<Float3>
    {
        /// <summary>The components.</summary>
        public float x, y, z;

        /// <summary>A vector of the given components.</summary>
        public Float3(float x, float y, float z) { this.x = x; this.y = y; this.z = z; }

        /// <summary>The zero vector.</summary>
        public static readonly Float3 zero = default;

        /// <summary>Component-wise sum.</summary>
        public static Float3 operator +(Float3 a, Float3 b) => new Float3(a.x + b.x, a.y + b.y, a.z + b.z);
        /// <summary>Component-wise difference.</summary>
        public static Float3 operator -(Float3 a, Float3 b) => new Float3(a.x - b.x, a.y - b.y, a.z - b.z);
        /// <summary>The vector negated.</summary>
        public static Float3 operator -(Float3 a) => new Float3(-a.x, -a.y, -a.z);
        /// <summary>Each component times <paramref name="s"/>.</summary>
        public static Float3 operator *(Float3 a, float s) => new Float3(a.x * s, a.y * s, a.z * s);
        /// <summary>Each component times <paramref name="s"/>.</summary>
        public static Float3 operator *(float s, Float3 a) => new Float3(a.x * s, a.y * s, a.z * s);
        /// <summary>Each component divided by <paramref name="s"/>.</summary>
        public static Float3 operator /(Float3 a, float s) => new Float3(a.x / s, a.y / s, a.z / s);

        /// <summary>True when no component is infinite or NaN.</summary>
        public bool IsFinite => GMath.isfinite(x) && GMath.isfinite(y) && GMath.isfinite(z);

        /// <inheritdoc/>
        public bool Equals(Float3 o) => x.Equals(o.x) && y.Equals(o.y) && z.Equals(o.z);
        /// <inheritdoc/>
        public override bool Equals(object obj) => obj is Float3 o && Equals(o);
        /// <inheritdoc/>
        public override int GetHashCode() => HashCode.Combine(x, y, z);
        /// <inheritdoc/>
        public override string ToString() => FormattableString.Invariant($"({x:R}, {y:R}, {z:R})");
    }
}
