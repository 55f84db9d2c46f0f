using System;

namespace GregoryTerrain
{
    /// <summary>Three doubles: control points are stored in double; the double evaluator is the reference.</summary>
    [Serializable]
    internal struct Double3 : IEquatable<Double3>
    {
        public double x, y, z;

        public Double3(double x, double y, double z) { this.x = x; this.y = y; this.z = z; }

        public static readonly Double3 zero = default;

        public static Double3 operator +(Double3 a, Double3 b) => new Double3(a.x + b.x, a.y + b.y, a.z + b.z);
        public static Double3 operator -(Double3 a, Double3 b) => new Double3(a.x - b.x, a.y - b.y, a.z - b.z);
        public static Double3 operator -(Double3 a) => new Double3(-a.x, -a.y, -a.z);
        public static Double3 operator *(Double3 a, double s) => new Double3(a.x * s, a.y * s, a.z * s);
        public static Double3 operator *(double s, Double3 a) => new Double3(a.x * s, a.y * s, a.z * s);
        public static Double3 operator /(Double3 a, double s) => new Double3(a.x / s, a.y / s, a.z / s);

        /// <summary>Rounds a double vector to float per component, as an upload to the GPU does.</summary>
        public static explicit operator Float3(Double3 d) => new Float3((float)d.x, (float)d.y, (float)d.z);
        public static implicit operator Double3(Float3 f) => new Double3(f.x, f.y, f.z);

        public bool IsFinite => GMath.isfinite(x) && GMath.isfinite(y) && GMath.isfinite(z);

        public bool Equals(Double3 o) => x.Equals(o.x) && y.Equals(o.y) && z.Equals(o.z);
        public override bool Equals(object obj) => obj is Double3 o && Equals(o);
        public override int GetHashCode() => HashCode.Combine(x, y, z);
        public override string ToString() => FormattableString.Invariant($"({x:R}, {y:R}, {z:R})");
    }
}
