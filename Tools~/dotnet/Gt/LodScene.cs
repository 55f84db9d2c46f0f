using System;
using System.Collections.Generic;
using System.IO;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// A ground-level view drawn with the levels of detail (GT_LOD; internals.md, "Levels of detail"):
    /// a terrain <see cref="TerrainMeters"/> wide, the camera <see cref="EyeMeters"/> above the surface
    /// at <see cref="Ground"/>, looking along +y a little down, the levels of Core's
    /// <see cref="LodLevels.Layout"/> around the ground point and the continuous octave rule on. What the
    /// harness needs: the inputs, the camera, and the bytes appended to TerrainParams
    /// (<c>_LodLevels</c>, <c>_Ranges[]</c>; <c>--params-tail</c>). Object space is terrain units
    /// (the unit square), so one metre is <c>1 / TerrainMeters</c>. Used by <c>gt-cli lod-scene</c>
    /// (the bench) and the rig's LOD tests.
    /// </summary>
    sealed class LodScene
    {
        public double TerrainMeters = 100000, EyeMeters = 2, FinestMeters = 16, FovYDegrees = 60;
        public Double2 Ground = new Double2(0.37, 0.52);
        public int Tiles = 16, Width = 1920, Height = 1080;
        /// <summary>Uniform factor (integer, for the readback), or 0 for the adaptive factors at <see cref="TargetPixels"/>.</summary>
        public int Factor;
        public float TargetPixels = 1f, MaxFactor = 64f, SegmentPixels = 2f;
        /// <summary>How far ahead (metres) the camera looks at the ground: sets the downward tilt.</summary>
        public double LookAheadMeters = 200;
        public NoiseSettings Noise = new NoiseSettings(0.004f, 16f, 2f, 2f, 6);
        /// <summary>
        /// The terrain width (metres) whose relief the scene keeps in metres: the grid's heights and the
        /// noise amplitude scale by <c>ReliefMeters / TerrainMeters</c> and the noise frequency by the
        /// inverse, so a 1,000 km terrain has the 100 km one's mountains and noise (same heights and
        /// wavelengths in metres), as a real terrain would, not ten times taller ones seen from the
        /// same 2 m. 0: <see cref="TerrainMeters"/> (the grid stretched, heights included).
        /// </summary>
        public double ReliefMeters = 100000;
        /// <summary>
        /// Whether the levels go up relative to a range origin near the camera (what the renderer does:
        /// RangeOrigin.For of the finest level), so the vertices output S(q) - S(O) from precise
        /// differences and the camera sits near 0 (precision.md). False: the plain absolute path.
        /// </summary>
        public bool UseOrigin = true;
        /// <summary>Whether far vertices take the levels' plain path (<see cref="TerrainVertex.UsesPlainPath"/>), as the renderer sends it; false: every vertex precise.</summary>
        public bool PlainPath = true;
        /// <summary>
        /// Whether the hull reads the factor kernels' records (<c>_LodLevels.y</c> = 1, the kernels
        /// dispatched by <see cref="KernelArgs"/>), as the renderer draws where compute runs; false:
        /// the hull computes the factors itself (the renderer's path without the kernels).
        /// </summary>
        public bool KernelFactors;
        /// <summary>
        /// The records the levels' vertex cache holds (<c>_LodLevels.z</c>; LevelVertexCacheKernels.hlsl,
        /// dispatched by <see cref="CacheKernelArgs"/> after the factor kernels, which it needs): the
        /// domain stage reads a tile's vertices from them. 0: it evaluates every vertex itself.
        /// </summary>
        public int CacheRecords { get; set; }
        /// <summary>The origin in use; <see cref="Build"/> picks one when unset, <see cref="Stepped"/> keeps it (as the renderer's tracker does for a small move).</summary>
        public RangeOrigin? Origin;

        /// <summary>The noise drawn: <see cref="Noise"/> with the relief's scale (<see cref="ReliefMeters"/>).</summary>
        public NoiseSettings DrawnNoise;
        public TerrainInputs Inputs;
        /// <summary>What the renderer adds to a vertex's output (terrain space, double): S(O) + p(O), or 0 without an origin.</summary>
        public Double3 OutputOffset;
        public RigCamera Camera;
        public TerrainRange[] Levels;
        public float[] Tail;

        public int LevelCount => Levels.Length;
        public int Patches => LevelCount * LodTiles.TilesPerLevel(Tiles);
        public double Meter => 1.0 / TerrainMeters;

        /// <summary>Lays the levels and the camera out over <paramref name="grid"/>.</summary>
        public LodScene Build(PatchGrid grid)
        {
            if (!(ReliefMeters >= 0) || double.IsInfinity(ReliefMeters)) throw new ArgumentException($"relief-m ({ReliefMeters}) must be >= 0 and finite", "relief-m");
            double relief = ReliefMeters > 0 ? ReliefMeters / TerrainMeters : 1.0;
            _source = grid;
            DrawnNoise = relief == 1.0 ? Noise
                : new NoiseSettings((float)(Noise.amplitude * relief), (float)(Noise.frequency / relief), Noise.alpha, Noise.beta, Noise.octaves);
            if (relief != 1.0) grid = ScaleHeights(grid, relief);
            if (Tiles % 2 != 0) throw new ArgumentException($"tiles ({Tiles}) must be even: a finer level covers M / 2 coarse tiles", "tiles");
            int n = LodLevels.FinestExponent(TerrainMeters, FinestMeters);
            var levels = new TerrainRange[LodLevels.LevelCount(n)];
            int count = LodLevels.Layout(Ground, n, Tiles, levels);
            if (count > LodTiles.MaxLevels) throw new ArgumentException($"{count} levels: at most {LodTiles.MaxLevels} (terrain-m / finest-m too large)", "terrain-m");
            Array.Resize(ref levels, count);
            Levels = levels;
            var tess = Factor > 0 ? TessellationSettings.Uniform(Tiles, Factor) : new TessellationSettings(Tiles, MaxFactor, TargetPixels, 0f);
            if (Origin == null) Origin = UseOrigin ? RangeOrigin.For(levels[0]) : RangeOrigin.zero;
            RangeOrigin origin = Origin.Value;
            TerrainParams p = TerrainParams.Create(grid, TerrainRange.full, origin, tess, DrawnNoise,
                new HeightColorSettings(0.25f, 0.15f, 24f), new Float3(0.2f, 0.3f, 0.1f), new Float3(0.8f, 0.8f, 0.8f));
            // The levels' plain path, as FramePlanner sends it (TerrainVertex.PlainPathError, OriginSurface).
            p.noiseOctaves = new Float4(p.noiseOctaves.x, p.noiseOctaves.y, SegmentPixels,
                                        PlainPath ? TerrainVertex.PlainPathError(grid, p, TerrainKeywords.Noise) : 0f);
            p.originSurface = TerrainVertex.OriginSurface(grid, p, TerrainKeywords.Noise);
            Inputs = TerrainInputs.Create(grid, p);
            Tail = new float[4 * (1 + LodTiles.MaxLevels)];
            Tail[0] = count;
            Tail[1] = KernelFactors ? 1f : 0f;
            if (CacheRecords < 0 || CacheRecords >= 1 << 24 || (CacheRecords > 0 && !KernelFactors))
                throw new ArgumentException($"cache-records ({CacheRecords}) must lie in [0, 2^24) and needs the factor kernels", "cache-records");
            Tail[2] = CacheRecords;
            for (int k = 0; k < count; k++)   // relative to the origin, as the renderer sends them
            {
                RangeMapping.EncodeRange(levels[k], origin, out Float4 r, out _);
                Tail[4 + 4 * k] = r.x;
                Tail[5 + 4 * k] = r.y;
                Tail[6 + 4 * k] = r.z;
                Tail[7 + 4 * k] = r.w;
            }
            _grid = grid;
            OutputOffset = TerrainVertex.OutputOffset(grid, p, TerrainKeywords.Noise);
            // The surface under the camera with every octave (the feet draw them all); the camera in
            // the vertices' frame (output minus the offset), built in double. RigCamera's reversed
            // depth, as Unity draws: with 0..1 depth a far ridge's hidden faces won the depth test in
            // speckles (RigCamera.LookAt).
            double ground = FullDetail(Ground.x, Ground.y).z;
            double[] eye = { Ground.x - OutputOffset.x, ground + EyeMeters * Meter - OutputOffset.z, Ground.y - OutputOffset.y };
            double[] target = { Ground.x - OutputOffset.x, ground - OutputOffset.z, Ground.y + LookAheadMeters * Meter - OutputOffset.y };
            Camera = RigCamera.LookAt(eye, target, FovYDegrees, Width, Height, 0.05 * Meter, 2.0, RigCamera.Scale(1, 1, 1));
            return this;
        }

        PatchGrid _grid, _source;

        /// <summary>The grid with every control point's height times <paramref name="k"/> (Gregory patches are affine invariant: the surface's heights times k).</summary>
        static PatchGrid ScaleHeights(PatchGrid grid, double k)
        {
            var patches = new GregoryPatch[grid.PatchCount];
            for (int p = 0; p < patches.Length; p++)
            {
                var points = new Double3[GregoryPatch.SlotCount];
                for (int c = 0; c < points.Length; c++)
                {
                    Double3 v = grid.Patches[p][c];
                    points[c] = new Double3(v.x, v.y, v.z * k);
                }
                patches[p] = new GregoryPatch(points);
            }
            return new PatchGrid(grid.Columns, grid.Rows, grid.XLines, grid.YLines, patches);
        }

        /// <summary>The full-detail surface in double (terrain space: x, y, height): Gregory + every noise octave.</summary>
        public Double3 FullDetail(double x, double y)
        {
            Double3 s = RelativeSurface.SurfaceAt(_grid, new Double2(x, y));
            s.z += OctaveNoise.Evaluate(x, y, DrawnNoise, DrawnNoise.octaves, out _);
            return s;
        }

        /// <summary>Level and tile of draw patch <paramref name="drawPatch"/> and the global point at tess (s, t) in double.</summary>
        public Double2 GlobalPoint(int drawPatch, double s, double t)
        {
            int level = LodTiles.LevelOfPatch(drawPatch, Tiles), slot = LodTiles.SlotOfPatch(drawPatch, Tiles);
            return RangeMapping.GlobalPoint(Levels[level], Tiles, slot % Tiles, slot / Tiles, s, t);
        }

        /// <summary>The exact point the drawn vertex at tess (s, t) of draw patch p stands for, in the vertices' object frame (x, height, y) minus the offset.</summary>
        public double[] ExactObjectPoint(int drawPatch, double s, double t)
        {
            Double2 q = GlobalPoint(drawPatch, s, t);
            Double3 e = FullDetail(q.x, q.y);
            return new[] { e.x - OutputOffset.x, e.z - OutputOffset.z, e.y - OutputOffset.y };
        }

        /// <summary>
        /// The vertex the GPU draws at tess (s, t) of draw patch p: Core's float mirror of the vertex
        /// stage (range mapping from the float levels and origin, the continuous octave rule at this
        /// camera), object space. Seam vertices form q through the coarse tile on the GPU; the same
        /// point to a float rounding.
        /// </summary>
        public double[] DrawnObjectPoint(int drawPatch, double s, double t)
        {
            int level = LodTiles.LevelOfPatch(drawPatch, Tiles), slot = LodTiles.SlotOfPatch(drawPatch, Tiles);
            var r = new Float4(Tail[4 + 4 * level], Tail[5 + 4 * level], Tail[6 + 4 * level], Tail[7 + 4 * level]);
            TerrainPoint q = RangeMapping.ToTerrainPoint(r, Inputs.Params.rangeOrigin, Tiles, slot % Tiles, slot / Tiles, (float)s, (float)t);
            Float3 v = TerrainVertex.EvaluateAtWithCamera(Inputs, q, TerrainKeywords.Noise, Camera.ObjectToClipFloat(), new Float2(Width, Height)).PositionOS;
            return new double[] { v.x, v.y, v.z };
        }

        /// <summary>The same scene drawn from a vertex cache of <paramref name="records"/> records (<see cref="CacheRecords"/>), laid out again.</summary>
        public LodScene WithCacheRecords(int records)
        {
            var s = (LodScene)MemberwiseClone();
            s.CacheRecords = records;
            return s.Build(_source);
        }

        /// <summary>The same scene with the camera moved <paramref name="meters"/> along +y (forward) and laid out again.</summary>
        public LodScene Stepped(double meters)
        {
            var s = (LodScene)MemberwiseClone();
            s.Ground = new Double2(Ground.x, Ground.y + meters * Meter);
            return s.Build(_source);
        }

        /// <summary>Writes the harness's --buffers folder and the --params-tail file (lod_tail.f32) into <paramref name="dir"/>.</summary>
        public void Write(string dir)
        {
            Directory.CreateDirectory(dir);
            BufferFiles.Write(Path.Combine(dir, "control_points.f32"), Inputs.ControlPoints);
            BufferFiles.Write(Path.Combine(dir, "regions.f32"), Inputs.Regions);
            BufferFiles.Write(Path.Combine(dir, "grid_lines.f32"), Inputs.GridLines);
            BufferFiles.Write(Path.Combine(dir, "params.f32"), Inputs.Params.Pack());
            BufferFiles.Write(Path.Combine(dir, "camera.f32"), Camera.Pack());
            BufferFiles.Write(Path.Combine(dir, "lod_tail.f32"), Tail);
        }

        /// <summary>The harness options that draw the scene from <paramref name="dir"/> (stages and output options are the caller's).</summary>
        public List<string> HarnessArgs(string dir) => new List<string>
        {
            "--buffers", dir, "--params-tail", Path.Combine(dir, "lod_tail.f32"), "--patches", Patches.ToString(),
            "--storage", FactorStorage, "--storage", CacheStorage,
        };

        /// <summary>The levels' records <c>_VertexCache</c> (binding 8): "8:BYTES", 16 bytes a record (no snow), declared either way.</summary>
        public string CacheStorage => FormattableString.Invariant($"8:{16 * Math.Max(1, CacheRecords)}");

        /// <summary>
        /// The levels' vertex cache kernels as the renderer dispatches them after the factor kernels:
        /// harness --compute options for the SPIR-V of LodVertexSlots (one group) and LodCacheVertices
        /// (M^2 x L x G groups, G for the largest factor the scene can draw).
        /// </summary>
        public string[] CacheKernelArgs(string slots, string vertices) => new[]
        {
            "--compute", FormattableString.Invariant($"{slots}:1,1,1"),
            "--compute", FormattableString.Invariant($"{vertices}:{LodTiles.TilesPerLevel(Tiles)},{LevelCount},{VertexCache.GroupsPerTile(VertexCache.FactorLimit(Inputs.Params.tess))}"),
        };

        /// <summary>The hull's <c>_LodFactors</c> (binding 7): "7:BYTES", read only with <see cref="KernelFactors"/>, declared either way.</summary>
        public string FactorStorage => FormattableString.Invariant($"7:{LodFactorRecord.Stride * Patches}");

        /// <summary>
        /// The factor kernels as the renderer dispatches them before the draw, every frame: harness
        /// --compute options for the SPIR-V of LodFactorPieces (a group a draw patch) and LodFactorSeams.
        /// </summary>
        public string[] KernelArgs(string pieces, string seams) => new[]
        {
            "--compute", FormattableString.Invariant($"{pieces}:{LodTiles.TilesPerLevel(Tiles)},{LevelCount},1"),
            "--compute", FormattableString.Invariant($"{seams}:{(Patches + 63) / 64},1,1"),
        };
    }
}
