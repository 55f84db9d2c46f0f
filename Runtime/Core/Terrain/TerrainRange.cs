using System;

namespace GregoryTerrain
{
    /// <summary>
    /// The range <c>[c, g] x [d, h]</c>: the part of the terrain's unit square that is drawn this frame
    /// (the paper's range info). Kept in double on the CPU; the GPU gets it through
    /// <c>RangeMapping.EncodeRange</c>.
    /// </summary>
    [Serializable]
    public struct TerrainRange : IEquatable<TerrainRange>
    {
        public double c, d, g, h;

        public TerrainRange(double c, double d, double g, double h) { this.c = c; this.d = d; this.g = g; this.h = h; }

        /// <summary>The whole terrain, <c>[0, 1] x [0, 1]</c>.</summary>
        public static readonly TerrainRange full = new TerrainRange(0.0, 0.0, 1.0, 1.0);

        /// <summary><c>g - c</c>, in terrain units.</summary>
        public double Width => g - c;
        /// <summary><c>h - d</c>, in terrain units.</summary>
        public double Height => h - d;

        public Double2 Min => new Double2(c, d);
        public Double2 Max => new Double2(g, h);
        public Double2 Center => new Double2(0.5 * (c + g), 0.5 * (d + h));

        /// <summary>
        /// Throws <see cref="ArgumentException"/> unless every field is finite, <c>c &lt; g</c>,
        /// <c>d &lt; h</c> and the range lies inside <c>[0, 1]</c> (touching an edge is allowed).
        /// </summary>
        public void Validate(string name = "range")
        {
            CheckUnit(name + ".c", c);
            CheckUnit(name + ".d", d);
            CheckUnit(name + ".g", g);
            CheckUnit(name + ".h", h);
            if (!(g > c))
                throw new ArgumentException(FormattableString.Invariant(
                    $"{name}.g ({g:R}) must be greater than {name}.c ({c:R})"), name);
            if (!(h > d))
                throw new ArgumentException(FormattableString.Invariant(
                    $"{name}.h ({h:R}) must be greater than {name}.d ({d:R})"), name);
        }

        static void CheckUnit(string field, double value)
        {
            if (!GMath.isfinite(value))
                throw new ArgumentException(FormattableString.Invariant($"{field} ({value:R}) must be finite"), field);
            if (value < 0.0 || value > 1.0)
                throw new ArgumentException(FormattableString.Invariant(
                    $"{field} ({value:R}) must lie in [0, 1]"), field);
        }

        public bool Equals(TerrainRange o) => c.Equals(o.c) && d.Equals(o.d) && g.Equals(o.g) && h.Equals(o.h);
        public override bool Equals(object obj) => obj is TerrainRange o && Equals(o);
        public override int GetHashCode() => HashCode.Combine(c, d, g, h);
        public override string ToString() => FormattableString.Invariant($"[{c:R}, {g:R}] x [{d:R}, {h:R}]");
    }
}
