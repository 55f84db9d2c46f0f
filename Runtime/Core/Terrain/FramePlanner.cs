using System;

namespace GregoryTerrain
{
    /// <summary>The renderer's settings a frame's constants are made from, as Core values.</summary>
    internal struct FrameSettings : IEquatable<FrameSettings>
    {
        public TessellationSettings tess;   // with the fallback, its grid's factor as the uniform factor
        public NoiseSettings noise;
        public HeightColorSettings heightColor;
        public Float3 colorLow, colorHigh;   // linear
        public float noiseVerticesAcross;
        public bool anchorTiles, levels, fallback;   // levels: the setting, with the tessellator

        /// <summary>Tiles anchored to the terrain: the setting, with adaptive factors, a tessellator and one range.</summary>
        public bool AnchorsTiles => anchorTiles && !fallback && tess.uniformFactor == 0f && !levels;

        public bool Equals(FrameSettings o) => tess.Equals(o.tess) && noise.Equals(o.noise) && heightColor.Equals(o.heightColor)
            && colorLow.Equals(o.colorLow) && colorHigh.Equals(o.colorHigh) && noiseVerticesAcross.Equals(o.noiseVerticesAcross)
            && anchorTiles == o.anchorTiles && levels == o.levels && fallback == o.fallback;
    }

    /// <summary>What the renderer reads from Unity for a frame.</summary>
    internal struct FrameInputs
    {
        public PatchGrid grid;
        public FrameSettings settings;
        public TerrainRange range;
        public TerrainKeywords noiseKeywords;   // GT_NOISE, GT_NOISE_TABLE: the output offset's noise
        // TerrainWorldFrame's parts
        public Float4x4 localToWorld;
        public Double2 terrainSize;
        public double heightScale;
        public Double3 worldOffset;
        // With the levels, each camera has its own origin and levels around its ground point (terrain units).
        public bool hasCamera;
        public int camera;
        public Double2 ground;
        public int finestExponent;
    }

    /// <summary>What a plan changed: the values to send.</summary>
    [Flags]
    internal enum FrameChange
    {
        None = 0,
        Params = 1,        // every float4 of TerrainParams
        Range = 2,
        RangeOrigin = 4,   // re-snapped, or another camera's
        TileLattice = 8,
        Matrices = 16,     // object-to-world and its inverse
        Levels = 32,       // _Ranges, every frame with the levels
        LevelCount = 64,   // _LodLevels
        Error = 128,       // a new FrameState.error to tell
    }

    /// <summary>The keywords a renderer sets on its runtime material copy.</summary>
    [Flags]
    internal enum FrameKeywords
    {
        None = 0,
        VertexCache = 1,
        Snow = 2,
        Levels = 4,
        RangeOrigin = 8,
    }

    /// <summary>What the property block holds and what it was made from; <see cref="FramePlanner.Plan"/> updates it in place.</summary>
    internal sealed class FrameState
    {
        public bool planned;
        public FrameSettings settings;
        public string error;   // why these settings draw nothing (Core's message), or null
        public TerrainParams parameters;   // range and origin current
        public RangeOrigin origin, sentOrigin;
        public readonly RangeOriginTracker rangeOrigin = new RangeOriginTracker();
        public readonly CameraRangeOrigins cameraOrigins = new CameraRangeOrigins();
        // Terrain space: what a deep-zoom vertex leaves out (a double Gregory evaluation plus the octaves),
        // its inputs, and the one before: two cameras with origins of their own switch without recomputing.
        public Double3 outputOffset, outputOffsetBefore;
        internal OffsetInputs offsetFor, offsetForBefore, originSurfaceFor, plainPathErrorFor;
        public Float4x4 frameMatrix;
        public Double2 frameSize;
        public double frameHeight;
        public Double3 frameOffset;
        public Float4x4 objectToWorld = Float4x4.identity, worldToObject = Float4x4.identity;
        public readonly TerrainRange[] levelRanges = new TerrainRange[LodTiles.MaxLevels];
        public readonly Float4[] levelVectors = new Float4[LodTiles.MaxLevels];   // relative to the camera's origin
        public int levelCount, sentLevelCount;
        // Buffers bound besides the grid's (GraphicsBuffer, opaque here).
        object _sentNoiseCells, _sentSnowDepth;
        Float3 _sentSnowMapSize;
        /// <summary>What the GPU objects and the draw material were made from.</summary>
        public readonly FrameResources resources = new FrameResources();

        /// <summary>The property block was cleared, or a plan's values never reached it: the next plan sends everything.</summary>
        public void Forget()
        {
            planned = false;
            sentOrigin = default;
            sentLevelCount = 0;
            offsetFor = offsetForBefore = originSurfaceFor = plainPathErrorFor = default;   // nor hold the grids' CPU copies of a disabled renderer
            _sentNoiseCells = _sentSnowDepth = null;
            _sentSnowMapSize = default;
        }

        /// <summary>True when the noise table must be set on the block (then taken as set).</summary>
        public bool BindNoiseCells(object table)
        {
            if (table == null || table == _sentNoiseCells) return false;   // off: the variants drawn do not read it
            _sentNoiseCells = table;
            return true;
        }

        /// <summary>True when the snow map (buffer, cells, depth cap) must be set on the block (then taken as set).</summary>
        public bool BindSnow(object depth, Float3 mapSize)
        {
            if (depth == _sentSnowDepth && mapSize.Equals(_sentSnowMapSize)) return false;
            (_sentSnowDepth, _sentSnowMapSize) = (depth, mapSize);
            return true;
        }

        /// <summary>A new grid: the origins snap afresh.</summary>
        public void ResetOrigins()
        {
            rangeOrigin.Reset();
            cameraOrigins.Reset();
        }

        internal readonly struct OffsetInputs
        {
            readonly PatchGrid _grid;
            readonly TerrainKeywords _keywords;
            readonly Float4 _origin, _noise;
            readonly float _octaves;

            public OffsetInputs(PatchGrid grid, TerrainKeywords keywords, in TerrainParams p) =>
                (_grid, _keywords, _origin, _noise, _octaves) = (grid, keywords, p.rangeOrigin, p.noise, TerrainVertex.OutputOffsetOctaves(p));

            // No grid (nothing computed yet) never matches.
            public bool Same(in OffsetInputs o) => _grid != null && _grid == o._grid && _keywords == o._keywords
                && _origin.Equals(o._origin) && _noise.Equals(o._noise) && _octaves.Equals(o._octaves);
        }
    }

    /// <summary>
    /// The renderer's per-frame rules (index.md, "What is sent per frame"): from the previous state and
    /// this frame's inputs, the new state and a mask of what to send. Steady: <c>_Range</c> alone (the
    /// levels add <c>_Ranges</c>); nothing allocated.
    /// </summary>
    internal static class FramePlanner
    {
        /// <summary>Pixels of a segment under the levels' continuous octave rule (<c>_NoiseOctaves.z</c>).</summary>
        public const float LevelSegmentPixels = 2f;

        public static FrameChange Plan(FrameState s, in FrameInputs f)
        {
            FrameChange c = FrameChange.None;
            bool levels = f.settings.levels && f.hasCamera;
            RangeOriginTracker tracker = levels ? s.cameraOrigins.For(f.camera) : s.rangeOrigin;
            TerrainRange originRange = f.range;   // with the levels the finest: the feet output S(q) - S(O) precisely
            if (levels && LevelsValid(f.settings))
            {
                s.levelCount = LodLevels.Layout(f.ground, f.finestExponent, f.settings.tess.tiles, s.levelRanges);
                originRange = s.levelRanges[0];
            }
            bool originMoved = tracker.Update(originRange);
            s.origin = tracker.Origin;
            originMoved |= !s.origin.Equals(s.sentOrigin);

            if (!s.planned || !f.settings.Equals(s.settings))
            {
                s.planned = true;
                s.settings = f.settings;
                string error = TryCreateParams(f, s.origin, out TerrainParams p);
                if (error != null) return SetError(s, error);
                s.parameters = p;
                s.originSurfaceFor = s.plainPathErrorFor = default;   // p's _OriginSurface and bound are 0: made again below
                s.sentOrigin = s.origin;
                c |= FrameChange.Params | FrameChange.Matrices;
            }
            else if (s.error != null) return FrameChange.None;   // drawn again after a change that fixes it
            else c |= SendRange(s, f.range, originMoved);

            c |= FollowLattice(s);
            if (UpdateOutputOffset(s, f.grid, f.noiseKeywords) | FrameMoved(s, f)) c |= FrameChange.Matrices;
            if (UpdateOriginSurface(s, f.grid, f.noiseKeywords) | UpdatePlainPathError(s, f.grid, f.noiseKeywords)) c |= FrameChange.Params;
            if ((c & FrameChange.Matrices) != 0)
            {
                string frameError = TryDrawMatrices(s, f);
                // Nothing of this plan reaches the block: the next drawable frame sends all of it.
                if (frameError != null) { s.Forget(); return SetError(s, frameError); }
            }
            s.error = null;
            if (levels) c |= EncodeLevels(s);
            return c;
        }

        /// <summary>The draw's matrices, or why the Transform cannot give them (a scale of 0: not invertible).</summary>
        static string TryDrawMatrices(FrameState s, in FrameInputs f)
        {
            try
            {
                var frame = new TerrainWorldFrame(f.localToWorld, f.terrainSize, f.heightScale, f.worldOffset);
                frame.DrawMatrices(TerrainVertex.TerrainToObject(s.outputOffset), out s.objectToWorld, out s.worldToObject);
                return null;
            }
            catch (ArgumentException e) { return e.Message; }
        }

        /// <summary>The draw's keywords: the range-origin variant only where its stages read the origin.</summary>
        public static FrameKeywords Keywords(FrameState s, bool cache, bool snow) =>
            (cache ? FrameKeywords.VertexCache : 0) | (snow ? FrameKeywords.Snow : 0) | (s.settings.levels ? FrameKeywords.Levels : 0)
            | (RelativeSurface.NeedsRangeOriginKeyword(s.parameters.rangeOrigin, s.settings.levels, cache) ? FrameKeywords.RangeOrigin : 0);

        /// <summary>The levels' settings check: M even and at least <see cref="LodLevels.MinTiles"/> (checked every frame: no message made).</summary>
        public static bool LevelsValid(in FrameSettings settings) =>
            !settings.levels || (settings.tess.tiles % 2 == 0 && settings.tess.tiles >= LodLevels.MinTiles);

        /// <summary>Why the levels cannot draw these settings, or null.</summary>
        public static string LevelsError(in FrameSettings settings) => LevelsValid(settings) ? null
            : $"tiles ({settings.tess.tiles}) must be even and at least {LodLevels.MinTiles} with Horizon Levels (a finer level covers M / 2 tiles of the coarser one)";

        /// <summary>Core's TerrainParams (every input validated), or the message naming the field and value.</summary>
        static string TryCreateParams(in FrameInputs f, RangeOrigin origin, out TerrainParams p)
        {
            p = default;
            FrameSettings st = f.settings;
            try
            {
                p = TerrainParams.Create(f.grid, f.range, origin, st.tess, st.noise, st.heightColor, st.colorLow, st.colorHigh, st.noiseVerticesAcross);
                if (!LevelsValid(st)) throw new ArgumentException(LevelsError(st), "tiles");
                // The continuous octave rule: both sides of a level seam draw the same noise.
                if (st.levels) p.noiseOctaves = new Float4(p.noiseOctaves.x, p.noiseOctaves.y, LevelSegmentPixels, 0f);
                return null;
            }
            catch (ArgumentException e) { return e.Message; }
        }

        static FrameChange SetError(FrameState s, string error)
        {
            FrameChange c = error != s.error ? FrameChange.Error : FrameChange.None;
            s.error = error;
            return c;
        }

        /// <summary><c>_Range</c>; <c>_RangeOrigin</c> when the origin moved (the lattice, in the old origin's coordinates, anchored again).</summary>
        static FrameChange SendRange(FrameState s, TerrainRange range, bool originMoved)
        {
            RangeMapping.EncodeRange(range, s.origin, out Float4 r, out Float4 o);
            s.parameters.range = r;
            s.parameters.rangeOrigin = o;
            if (!originMoved) return FrameChange.Range;
            s.sentOrigin = s.origin;
            s.parameters.tileLattice = default;
            return FrameChange.Range | FrameChange.RangeOrigin;
        }

        /// <summary>Anchored tiles: kept while the range pans, anchored again on a zoom, re-snap or settings change; 0 on the range.</summary>
        static FrameChange FollowLattice(FrameState s)
        {
            Float4 lattice = s.settings.AnchorsTiles ? TileLattice.Follow(s.parameters.tileLattice, s.parameters.range, s.settings.tess.tiles) : default;
            if (lattice.Equals(s.parameters.tileLattice)) return FrameChange.None;
            s.parameters = s.parameters.WithTileLattice(lattice);
            return FrameChange.TileLattice;
        }

        static bool UpdateOutputOffset(FrameState s, PatchGrid grid, TerrainKeywords keywords)
        {
            var inputs = new FrameState.OffsetInputs(grid, keywords, s.parameters);
            if (inputs.Same(s.offsetFor)) return false;
            Double3 offset = inputs.Same(s.offsetForBefore) ? s.outputOffsetBefore
                : grid == null ? Double3.zero : TerrainVertex.OutputOffset(grid, s.parameters, keywords);
            (s.offsetForBefore, s.outputOffsetBefore) = (s.offsetFor, s.outputOffset);
            s.offsetFor = inputs;
            if (offset.Equals(s.outputOffset)) return false;
            s.outputOffset = offset;
            return true;
        }

        /// <summary>The levels' <c>_OriginSurface</c>, made again with the output offset's inputs; true when it changed.</summary>
        static bool UpdateOriginSurface(FrameState s, PatchGrid grid, TerrainKeywords keywords)
        {
            if (s.originSurfaceFor.Same(s.offsetFor)) return false;
            s.originSurfaceFor = s.offsetFor;
            Float4 o = s.settings.levels && grid != null ? TerrainVertex.OriginSurface(grid, s.parameters, keywords) : default;
            if (o.Equals(s.parameters.originSurface)) return false;
            s.parameters.originSurface = o;
            return true;
        }

        /// <summary>
        /// The levels' plain-path bound (<c>_NoiseOctaves.w</c>), made again when the grid, the noise keywords
        /// (the material's, not the settings) or the noise change, not when the origin moves: it reads every
        /// control point. True when it changed.
        /// </summary>
        static bool UpdatePlainPathError(FrameState s, PatchGrid grid, TerrainKeywords keywords)
        {
            if (!s.settings.levels || grid == null) return false;
            TerrainParams p = s.parameters;
            p.rangeOrigin = default;
            var inputs = new FrameState.OffsetInputs(grid, keywords, p);
            if (inputs.Same(s.plainPathErrorFor)) return false;
            s.plainPathErrorFor = inputs;
            float e = TerrainVertex.PlainPathError(grid, p, keywords);
            Float4 o = s.parameters.noiseOctaves;
            if (e.Equals(o.w)) return false;
            s.parameters.noiseOctaves = new Float4(o.x, o.y, o.z, e);
            return true;
        }

        // Compared, not Transform.hasChanged, which another script may clear.
        static bool FrameMoved(FrameState s, in FrameInputs f)
        {
            if (f.localToWorld.Equals(s.frameMatrix) && f.terrainSize.Equals(s.frameSize) && f.heightScale.Equals(s.frameHeight) && f.worldOffset.Equals(s.frameOffset))
                return false;
            s.frameMatrix = f.localToWorld; s.frameSize = f.terrainSize; s.frameHeight = f.heightScale; s.frameOffset = f.worldOffset;
            return true;
        }

        static FrameChange EncodeLevels(FrameState s)
        {
            for (int k = 0; k < s.levelCount; k++)
            {
                RangeMapping.EncodeRange(s.levelRanges[k], s.origin, out Float4 r, out _);
                s.levelVectors[k] = r;
            }
            if (s.levelCount == s.sentLevelCount) return FrameChange.Levels;
            s.sentLevelCount = s.levelCount;
            return FrameChange.Levels | FrameChange.LevelCount;
        }
    }
}
