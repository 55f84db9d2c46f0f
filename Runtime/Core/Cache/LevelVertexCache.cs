using System;

namespace GregoryTerrain
{
    /// <summary>
    /// The Horizon levels' vertex cache layout (internals.md, "Levels of detail"), name for name as
    /// <c>Shaders/Cache/LevelVertexCache.hlsl</c>: every drawn tile of every level is evaluated again
    /// each frame the levels draw, so records need not persist and take a compact layout made again
    /// each frame. A draw patch (<see cref="LodTiles"/>: tile <c>p mod M^2</c> of level <c>p / M^2</c>) at integer
    /// factors f takes <see cref="VertexCache.SlotsPerTile"/> of its largest factor (its own L: the
    /// single range's slot rule, <see cref="VertexCache.Slot"/>, unchanged), a culled one none, and
    /// its records start at the exclusive prefix sum of the slots before it.
    /// </summary>
    internal static class LevelVertexCache
    {
        /// <summary>Records a buffer holds at most: C (<c>_LodLevels.z</c>) and first records are floats, exact below 2^24.</summary>
        public const int MaxRecords = 1 << 24;

        /// <summary>
        /// The bytes a buffer bound whole may hold: Vulkan guarantees a storage buffer range of 2^27 bytes
        /// (maxStorageBufferRange), which may be below the largest buffer a device allocates.
        /// </summary>
        public const long MaxBoundBytes = 1L << 27;

        /// <summary>
        /// The records a buffer of <paramref name="recordBytes"/>-byte records can hold: <see cref="MaxRecords"/>,
        /// <see cref="MaxBoundBytes"/> and the device's largest buffer (<paramref name="maxBufferBytes"/>; Unity:
        /// <c>SystemInfo.maxGraphicsBufferSize</c>, 0 when unknown; <see cref="GpuLayout.MaxBufferBytes"/> at most).
        /// </summary>
        public static int RecordLimit(int recordBytes, long maxBufferBytes)
        {
            long bytes = Math.Min(MaxBoundBytes, maxBufferBytes > 0 ? Math.Min(maxBufferBytes, GpuLayout.MaxBufferBytes) : GpuLayout.MaxBufferBytes);
            return (int)Math.Min(MaxRecords, bytes / recordBytes);
        }

        /// <summary>A camera's first buffer: a 16th of S(<paramref name="factorLimit"/>) a drawn tile; it grows (<see cref="GrownRecords"/>).</summary>
        public static int FirstRecords(int drawnTiles, int factorLimit)
        {
            if (drawnTiles < 0) throw new ArgumentOutOfRangeException(nameof(drawnTiles), drawnTiles, "drawnTiles must be >= 0");
            return (int)Math.Clamp((long)drawnTiles * VertexCache.SlotsPerTile(factorLimit) / 16, 1, MaxRecords);
        }

        /// <summary>The buffer after a frame needed <paramref name="needed"/>: kept while they fit, else a quarter above.</summary>
        public static int GrownRecords(long needed, int current) =>
            needed <= current ? current : (int)Math.Min(MaxRecords, needed + needed / 4);

        /// <summary>The largest of a tile's six integer factors: its slot rule's L. 0 when culled.</summary>
        public static int TileFactorLimit(TileFactorSet integerFactors)
        {
            if (integerFactors.IsCulled) return 0;
            Float4 e = integerFactors.edge;
            Float2 i = integerFactors.inside;
            return Math.Max(Math.Max(Math.Max(CheckFactor(e.x, integerFactors), CheckFactor(e.y, integerFactors)), Math.Max(CheckFactor(e.z, integerFactors), CheckFactor(e.w, integerFactors))),
                            Math.Max(CheckFactor(i.x, integerFactors), CheckFactor(i.y, integerFactors)));
        }

        /// <summary>One integer factor of <paramref name="set"/>; throws naming the set unless it is an integer in [1, 64].</summary>
        static int CheckFactor(float f, TileFactorSet set)
        {
            if (!(f >= 1f && f <= VertexCache.MaxFactor) || f != MathF.Floor(f))
                throw new ArgumentException(FormattableString.Invariant($"integerFactors ({set}) must be integers in [1, {VertexCache.MaxFactor}] (VertexCache.IntegerFactors) or culled"), "integerFactors");
            return (int)f;
        }

        /// <summary>The slots a draw patch at <paramref name="integerFactors"/> takes: S(its own L), or 0 when culled.</summary>
        public static int TileSlots(TileFactorSet integerFactors)
        {
            int limit = TileFactorLimit(integerFactors);
            return limit == 0 ? 0 : VertexCache.SlotsPerTile(limit);
        }

        /// <summary>
        /// Each draw patch's first record (the exclusive prefix sum of <see cref="TileSlots"/>) into
        /// <paramref name="firstRecords"/>; returns the records the frame needs. Throws when the spans'
        /// lengths differ; writes nothing then.
        /// </summary>
        public static long TileFirstRecords(ReadOnlySpan<TileFactorSet> integerFactors, Span<long> firstRecords)
        {
            if (firstRecords.Length != integerFactors.Length)
                throw new ArgumentException(FormattableString.Invariant($"firstRecords.Length ({firstRecords.Length}) must equal integerFactors.Length ({integerFactors.Length}), one a draw patch"), nameof(firstRecords));
            long next = 0;
            for (int p = 0; p < integerFactors.Length; p++)
            {
                firstRecords[p] = next;
                next += TileSlots(integerFactors[p]);
            }
            return next;
        }

        /// <summary>HLSL <c>LevelVertexCachePointTess</c>: the kernel's exact point (k / F, i / Iu) for the tessellator's <paramref name="tess"/>.</summary>
        public static Float2 PointTess(Float2 tess, TileFactorSet integerFactors)
        {
            Float4 e = integerFactors.edge;
            if (tess.x == 0f) return VertexCache.EdgeTess(0, (int)VertexCache.RoundToPoint(tess.y * e.x), e.x);
            if (tess.y == 0f) return VertexCache.EdgeTess(1, (int)VertexCache.RoundToPoint(tess.x * e.y), e.y);
            if (tess.x == 1f) return VertexCache.EdgeTess(2, (int)VertexCache.RoundToPoint(tess.y * e.z), e.z);
            if (tess.y == 1f) return VertexCache.EdgeTess(3, (int)VertexCache.RoundToPoint(tess.x * e.w), e.w);
            Float2 i = integerFactors.inside;
            return new Float2(VertexCache.RoundToPoint(tess.x * i.x) / i.x, VertexCache.RoundToPoint(tess.y * i.y) / i.y);
        }

        /// <summary>The record of the vertex the tessellator puts at <paramref name="tess"/> in a draw patch whose records start at <paramref name="firstRecord"/>.</summary>
        public static long Record(long firstRecord, Float2 tess, TileFactorSet integerFactors) =>
            firstRecord + VertexCache.Slot(tess, integerFactors, TileFactorLimit(integerFactors));
    }
}
