using System;

namespace GregoryTerrain
{
    /// <summary>
    /// Where the terrain is in the world, in double (internals.md, "World units and the floating
    /// origin"): the Transform's matrices (position and rotation; a scale there multiplies too), the
    /// terrain's size in metres (<see cref="terrainSize"/> across terrain x and y), its
    /// <see cref="heightScale"/> (metres per terrain height unit) and a floating-origin
    /// <see cref="worldOffset"/> the application moves with <see cref="Shifted"/>. Object space is the
    /// shaders' (terrain x, height, terrain y); world = <c>offset + L (S o)</c>, L the Transform's
    /// localToWorld, <c>S = diag(terrainSize.x, heightScale, terrainSize.y)</c>. The renderer's draw
    /// matrices, its CPU queries and the collider all go through one frame, so they agree.
    /// </summary>
    internal readonly struct TerrainWorldFrame
    {
        /// <summary>The Transform's localToWorld (float entries, as Unity holds them).</summary>
        public readonly Float4x4 localToWorld;
        // The exact inverse of localToWorld's 3x3, in double (rows), and of its translation. Not Unity's
        // float worldToLocal: that is the inverse only to float precision, and a world point 300 km from
        // the Transform would come back centimetres off (a query would not find what the draw shows).
        readonly Double3 _inverseRow0, _inverseRow1, _inverseRow2;
        /// <summary>Metres across terrain x and terrain y (the unit square's sides).</summary>
        public readonly Double2 terrainSize;
        /// <summary>Metres per terrain height unit.</summary>
        public readonly double heightScale;
        /// <summary>The floating-origin shift added to every world position, in double.</summary>
        public readonly Double3 worldOffset;

        /// <summary>Throws ArgumentException naming the field unless the sizes are finite and positive and the offset finite.</summary>
        public TerrainWorldFrame(Float4x4 localToWorld, Double2 terrainSize, double heightScale, Double3 worldOffset)
        {
            CheckScale(terrainSize, heightScale);
            if (!worldOffset.IsFinite) throw new ArgumentException(FormattableString.Invariant($"worldOffset {worldOffset} must be finite"), nameof(worldOffset));
            if (!localToWorld.IsFinite) throw new ArgumentException("localToWorld must be finite", nameof(localToWorld));
            Double3 a = Column(localToWorld.c0), b = Column(localToWorld.c1), c = Column(localToWorld.c2);
            double det = GMath.dot(a, Cross(b, c));
            if (!(Math.Abs(det) > 0.0) || double.IsInfinity(det))
                throw new ArgumentException(FormattableString.Invariant($"localToWorld (the Transform) must be invertible, its determinant is {det:R}"), nameof(localToWorld));
            // Rows of the inverse: (b x c, c x a, a x b) / det.
            _inverseRow0 = Cross(b, c) * (1.0 / det);
            _inverseRow1 = Cross(c, a) * (1.0 / det);
            _inverseRow2 = Cross(a, b) * (1.0 / det);
            this.localToWorld = localToWorld;
            this.terrainSize = terrainSize;
            this.heightScale = heightScale;
            this.worldOffset = worldOffset;
        }

        /// <summary>Throws ArgumentException naming <c>terrainSize</c> or <c>heightScale</c> unless finite and positive.</summary>
        public static void CheckScale(Double2 terrainSize, double heightScale)
        {
            if (!(terrainSize.x > 0.0) || !(terrainSize.y > 0.0) || !terrainSize.IsFinite)
                throw new ArgumentException(FormattableString.Invariant($"terrainSize ({terrainSize.x:R}, {terrainSize.y:R}) must be finite and greater than 0 (metres across terrain x and y)"), nameof(terrainSize));
            if (!(heightScale > 0.0) || double.IsInfinity(heightScale))
                throw new ArgumentException(FormattableString.Invariant($"heightScale ({heightScale:R}) must be finite and greater than 0 (metres per terrain height unit)"), nameof(heightScale));
        }

        /// <summary>The same frame after the application moved the world by <paramref name="delta"/> (floating origin).</summary>
        public TerrainWorldFrame Shifted(Double3 delta)
        {
            if (!delta.IsFinite) throw new ArgumentException(FormattableString.Invariant($"delta {delta} must be finite"), nameof(delta));
            return new TerrainWorldFrame(localToWorld, terrainSize, heightScale, worldOffset + delta);
        }

        /// <summary>S: object units to the Transform's local metres, per object axis (x, height, y).</summary>
        public Double3 Scale => new Double3(terrainSize.x, heightScale, terrainSize.y);

        /// <summary>World units per object unit along each object axis (the Transform's own scale included).</summary>
        public Double3 ObjectScale => new Double3(terrainSize.x * Length(localToWorld.c0), heightScale * Length(localToWorld.c1), terrainSize.y * Length(localToWorld.c2));

        /// <summary>An object point (x, height, y) to world, in double.</summary>
        public Double3 ObjectToWorld(Double3 o)
        {
            Double3 s = Scale;
            return Affine(localToWorld, new Double3(o.x * s.x, o.y * s.y, o.z * s.z), 1.0) + worldOffset;
        }

        /// <summary>A world point to object (x, height, y), in double.</summary>
        public Double3 WorldToObject(Double3 w)
        {
            Double3 l = InverseLinear(w - worldOffset - Column(localToWorld.c3)), s = Scale;
            return new Double3(l.x / s.x, l.y / s.y, l.z / s.z);
        }

        /// <summary>
        /// A terrain point (x, y across the unit square, z height: a control point as the grid stores
        /// it) to world, in double: the point the renderer draws there (object = terrain (x, z, y)).
        /// </summary>
        public Double3 TerrainToWorld(Double3 t) => ObjectToWorld(TerrainVertex.TerrainToObject(t));

        /// <summary>A world point to terrain (x, y, height z), in double: the inverse of <see cref="TerrainToWorld"/>.</summary>
        public Double3 WorldToTerrain(Double3 w) => TerrainVertex.TerrainToObject(WorldToObject(w));

        /// <summary>A world direction to object (not normalized).</summary>
        public Double3 DirectionToObject(Double3 d)
        {
            Double3 l = InverseLinear(d), s = Scale;
            return new Double3(l.x / s.x, l.y / s.y, l.z / s.z);
        }

        /// <summary>An object normal to a world unit normal (the inverse transpose: <c>(S^-1 L^-1)^T n</c>).</summary>
        public Double3 NormalToWorld(Double3 n)
        {
            Double3 s = Scale;
            Double3 m = new Double3(n.x / s.x, n.y / s.y, n.z / s.z);
            // (L3^-1)^T m: the inverse's rows weighted by m.
            return GMath.normalize(_inverseRow0 * m.x + _inverseRow1 * m.y + _inverseRow2 * m.z);
        }

        /// <summary>
        /// The draw matrices for an object-space output offset <paramref name="t"/> (the deep-zoom
        /// reference point, object (x, height, y)): <c>M = T(offset) L S T(t)</c> and its inverse
        /// <c>T(-t) S^-1 L^-1 T(-offset)</c>, every entry formed in double and rounded once. The
        /// translation then holds <c>offset + L.t + L S t</c>: near the camera it is small even when each
        /// part is hundreds of kilometres, which a float product on the GPU could not give.
        /// </summary>
        public void DrawMatrices(Double3 t, out Float4x4 objectToWorld, out Float4x4 worldToObject)
        {
            Double3 s = Scale;
            Float4x4 l = localToWorld;
            Double3 translation = Affine(l, new Double3(t.x * s.x, t.y * s.y, t.z * s.z), 1.0) + worldOffset;
            objectToWorld = new Float4x4(
                (Float4)(ToDouble4(l.c0) * s.x), (Float4)(ToDouble4(l.c1) * s.y), (Float4)(ToDouble4(l.c2) * s.z),
                new Float4((float)translation.x, (float)translation.y, (float)translation.z, 1f));
            // Rows of S^-1 L3^-1; translation S^-1 L3^-1 (-L.t - offset) - t.
            Double3 lt = InverseLinear(-Column(l.c3) - worldOffset);
            Double3 inverseT = new Double3(lt.x / s.x - t.x, lt.y / s.y - t.y, lt.z / s.z - t.z);
            Double3 r0 = _inverseRow0 * (1.0 / s.x), r1 = _inverseRow1 * (1.0 / s.y), r2 = _inverseRow2 * (1.0 / s.z);
            worldToObject = Float4x4.FromRows(
                (float)r0.x, (float)r0.y, (float)r0.z, (float)inverseT.x,
                (float)r1.x, (float)r1.y, (float)r1.z, (float)inverseT.y,
                (float)r2.x, (float)r2.y, (float)r2.z, (float)inverseT.z,
                0f, 0f, 0f, 1f);
        }

        static Double3 Affine(Float4x4 m, Double3 p, double w) => new Double3(
            (double)m.c0.x * p.x + (double)m.c1.x * p.y + (double)m.c2.x * p.z + (double)m.c3.x * w,
            (double)m.c0.y * p.x + (double)m.c1.y * p.y + (double)m.c2.y * p.z + (double)m.c3.y * w,
            (double)m.c0.z * p.x + (double)m.c1.z * p.y + (double)m.c2.z * p.z + (double)m.c3.z * w);

        Double3 InverseLinear(Double3 v) => new Double3(GMath.dot(_inverseRow0, v), GMath.dot(_inverseRow1, v), GMath.dot(_inverseRow2, v));

        static Double3 Column(Float4 c) => new Double3(c.x, c.y, c.z);

        static Double3 Cross(Double3 a, Double3 b) => new Double3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);

        static double Length(Float4 c) => Math.Sqrt((double)c.x * c.x + (double)c.y * c.y + (double)c.z * c.z);

        static Double4 ToDouble4(Float4 c) => new Double4(c.x, c.y, c.z, c.w);

        /// <summary>Four doubles: a column scaled in double before its one rounding.</summary>
        readonly struct Double4
        {
            readonly double x, y, z, w;
            public Double4(double x, double y, double z, double w) { this.x = x; this.y = y; this.z = z; this.w = w; }
            public static Double4 operator *(Double4 a, double s) => new Double4(a.x * s, a.y * s, a.z * s, a.w * s);
            public static explicit operator Float4(Double4 a) => new Float4((float)a.x, (float)a.y, (float)a.z, (float)a.w);
        }
    }
}
