using System;

namespace GregoryTerrain
{
    /// <summary>Two doubles: the reference arithmetic for ranges and global points.</summary>
    [Serializable]
    internal struct Double2 : IEquatable<Double2>
    {
        public double x, y;

        public Double2(double x, double y) { this.x = x; this.y = y; }

        public static Double2 operator +(Double2 a, Double2 b) => new Double2(a.x + b.x, a.y + b.y);
        public static Double2 operator -(Double2 a, Double2 b) => new Double2(a.x - b.x, a.y - b.y);
        public static Double2 operator *(Double2 a, double s) => new Double2(a.x * s, a.y * s);
        public static Double2 operator *(double s, Double2 a) => new Double2(a.x * s, a.y * s);

        public static explicit operator Float2(Double2 d) => new Float2((float)d.x, (float)d.y);
        public static implicit operator Double2(Float2 f) => new Double2(f.x, f.y);

        public bool IsFinite => GMath.isfinite(x) && GMath.isfinite(y);

        public bool Equals(Double2 o) => x.Equals(o.x) && y.Equals(o.y);
        public override bool Equals(object obj) => obj is Double2 o && Equals(o);
        public override int GetHashCode() => HashCode.Combine(x, y);
        public override string ToString() => FormattableString.Invariant($"({x:R}, {y:R})");
    }
}
