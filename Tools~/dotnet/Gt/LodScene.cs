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

        public TerrainInputs Inputs;
        public RigCamera Camera;
        public TerrainRange[] Levels;
        public float[] Tail;

        public int LevelCount => Levels.Length;
        public int Patches => LevelCount * LodTiles.TilesPerLevel(Tiles);
        public double Meter => 1.0 / TerrainMeters;

        /// <summary>Lays the levels and the camera out over <paramref name="grid"/>.</summary>
        public LodScene Build(PatchGrid grid)
        {
            if (Tiles % 2 != 0) throw new ArgumentException($"tiles ({Tiles}) must be even: a finer level covers M / 2 coarse tiles", "tiles");
            int n = LodLevels.FinestExponent(TerrainMeters, FinestMeters);
            var levels = new TerrainRange[LodLevels.LevelCount(n)];
            int count = LodLevels.Layout(Ground, n, Tiles, levels);
            if (count > LodTiles.MaxLevels) throw new ArgumentException($"{count} levels: at most {LodTiles.MaxLevels} (terrain-m / finest-m too large)", "terrain-m");
            Array.Resize(ref levels, count);
            Levels = levels;
            var tess = Factor > 0 ? TessellationSettings.Uniform(Tiles, Factor) : new TessellationSettings(Tiles, MaxFactor, TargetPixels, 0f);
            TerrainParams p = TerrainParams.Create(grid, TerrainRange.full, RangeOrigin.zero, tess, Noise,
                new HeightColorSettings(0.25f, 0.15f, 24f), new Float3(0.2f, 0.3f, 0.1f), new Float3(0.8f, 0.8f, 0.8f));
            p.noiseOctaves = new Float4(p.noiseOctaves.x, p.noiseOctaves.y, SegmentPixels, 0f);
            Inputs = TerrainInputs.Create(grid, p);
            Tail = new float[4 * (1 + LodTiles.MaxLevels)];
            Tail[0] = count;
            for (int k = 0; k < count; k++)   // dyadic: exact in float
            {
                Tail[4 + 4 * k] = (float)levels[k].c;
                Tail[5 + 4 * k] = (float)levels[k].d;
                Tail[6 + 4 * k] = (float)levels[k].g;
                Tail[7 + 4 * k] = (float)levels[k].h;
            }
            // The surface under the camera with every octave (the feet draw them all).
            var full = TerrainInputs.Create(grid, TerrainParams.Create(grid, TerrainRange.full, RangeOrigin.zero, tess, Noise,
                new HeightColorSettings(0.25f, 0.15f, 24f), new Float3(0.2f, 0.3f, 0.1f), new Float3(0.8f, 0.8f, 0.8f), 1e9f));
            double ground = TerrainVertex.EvaluateAt(full, TerrainPoint.FromFloat(new Float2((float)Ground.x, (float)Ground.y)), TerrainKeywords.Noise).position.z;
            double[] eye = { Ground.x, ground + EyeMeters * Meter, Ground.y };
            double[] target = { Ground.x, ground, Ground.y + LookAheadMeters * Meter };
            Camera = RigCamera.LookAt(eye, target, FovYDegrees, Width, Height, 0.05 * Meter, 2.0, RigCamera.Scale(1, 1, 1));
            return this;
        }

        /// <summary>The same scene with the camera moved <paramref name="meters"/> along +y (forward) and laid out again.</summary>
        public LodScene Stepped(PatchGrid grid, double meters)
        {
            var s = (LodScene)MemberwiseClone();
            s.Ground = new Double2(Ground.x, Ground.y + meters * Meter);
            return s.Build(grid);
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
        };
    }
}
