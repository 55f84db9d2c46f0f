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
        /// <summary>The range <c>[c, g] x [d, h]</c>: left, bottom, right and top edges in the terrain unit square.</summary>
        public double c, d, g, h;

        /// <summary>The range <c>[c, g] x [d, h]</c>; call <see cref="Validate"/> to check it.</summary>
        public TerrainRange(double c, double d, double g, double h) { this.c = c; this.d = d; this.g = g; this.h = h; }

        /// <summary>The whole terrain, <c>[0, 1] x [0, 1]</c>.</summary>
        public static readonly TerrainRange full = new TerrainRange(0.0, 0.0, 1.0, 1.0);

        /// <summary><c>g - c</c>, in terrain units.</summary>
        public double Width => g - c;
        /// <summary><c>h - d</c>, in terrain units.</summary>
        public double Height => h - d;

        internal Double2 Min => new Double2(c, d);
        internal Double2 Max => new Double2(g, h);
        internal Double2 Center => new Double2(0.5 * (c + g), 0.5 * (d + h));

        /// <summary>
        /// The narrowest range drawn: 1e-10 of the terrain. Local offsets keep ~1e-13 in float
        /// (precision.md), about one pixel of an 800-pixel view at this width; narrower views repeat
        /// vertices and then overflow the view scale. The controllers stop at 1e-7 (RangeFit.MinWidth).
        /// </summary>
        public const double MinSize = 1e-10;

        /// <summary>
        /// Throws <see cref="ArgumentException"/> unless every field is finite, <c>c &lt; g</c>,
        /// <c>d &lt; h</c>, width and height are at least <see cref="MinSize"/> and the range lies
        /// inside <c>[0, 1]</c> (touching an edge is allowed).
        /// </summary>
        public void Validate(string name = "range")
        {
            if (IsValid) return;   // no field-name strings: the renderer checks every level every frame
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
            CheckSize(name + " width (g - c)", g - c);
            CheckSize(name + " height (h - d)", h - d);
        }

        /// <summary>Whether <see cref="Validate"/> passes (a value in [0, 1] is finite).</summary>
        bool IsValid => InUnit(c) && InUnit(d) && InUnit(g) && InUnit(h) && g > c && h > d && g - c >= MinSize && h - d >= MinSize;

        static bool InUnit(double value) => value >= 0.0 && value <= 1.0;

        /// <summary>Throws ArgumentException naming <paramref name="field"/> unless <paramref name="size"/> is at least <see cref="MinSize"/>.</summary>
        public static void CheckSize(string field, double size)
        {
            if (!(size >= MinSize))
                throw new ArgumentException(FormattableString.Invariant(
                    $"{field} = {size:R} is narrower than the smallest range drawn, {MinSize:R} (float keeps ~1e-13 of a local offset)"), field);
        }

        static void CheckUnit(string field, double value)
        {
            if (!GMath.isfinite(value))
                throw new ArgumentException(FormattableString.Invariant($"{field} ({value:R}) must be finite"), field);
            if (value < 0.0 || value > 1.0)
                throw new ArgumentException(FormattableString.Invariant(
                    $"{field} ({value:R}) must lie in [0, 1]"), field);
        }

        /// <inheritdoc/>
        public bool Equals(TerrainRange o) => c.Equals(o.c) && d.Equals(o.d) && g.Equals(o.g) && h.Equals(o.h);
        /// <inheritdoc/>
        public override bool Equals(object obj) => obj is TerrainRange o && Equals(o);
        /// <inheritdoc/>
        public override int GetHashCode() => HashCode.Combine(c, d, g, h);
        /// <inheritdoc/>
        public override string ToString() => FormattableString.Invariant($"[{c:R}, {g:R}] x [{d:R}, {h:R}]");
    }
}
