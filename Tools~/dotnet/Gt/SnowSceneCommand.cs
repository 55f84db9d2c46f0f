using System;
using System.IO;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// gt-cli snow-scene: everything a snow run needs, in one folder (the input of
    /// Tools~/rig/snow-device.sh and of the snow pictures):
    /// <code>
    ///   grid.json                  a ridge across the wind (fitted Gregory grid), unless --grid is given
    ///   scene/*.f32                the harness's buffers: params, camera (a view of both faces), grid
    ///   field_params_R.f32         TerrainParams of SnowFieldKernel at R (SnowFieldTerrain.ParamsFor)
    ///   snow_params_R.f32          SnowParams of the simulation at R (SnowSettings.Params(dt).Pack())
    ///   snow_size_R.f32            _SnowMapSize at R (the harness's --snow-params)
    ///   cpu_depth_R.f32            with --cpu: the Core reference's depth after the run (R*R floats)
    ///   run.txt                    "resolutions ...", "steps N", "dt X", "keywords ..." for the script
    /// </code>
    /// Wind along +x: the ridge's west face (x &lt; 0.5) faces the wind, its east face is the lee.
    /// </summary>
    static class SnowSceneCommand
    {
        public static int Run(Args a)
        {
            string dir = a.String("out");
            var resolutions = a.Ints("resolutions", "256,512,1024,2048");
            int steps = a.Int("steps", 40), width = a.Int("width", 640), height = a.Int("height", 480);
            float dt = (float)a.Double("dt", 0.25);
            bool cpu = a.Flag("cpu"), noise = !a.Flag("no-noise");
            Directory.CreateDirectory(dir);

            PatchGrid grid;
            string gridPath = a.Flag("grid") ? a.String("grid") : null;
            if (gridPath != null) grid = PatchGridJson.ReadFile(gridPath);
            else
            {
                const int samples = 129;
                var fit = HeightmapFitter.Fit(RidgeHeightmap(samples), samples, samples, a.Int("patches", 6), a.Int("patches", 6));
                grid = fit.Grid;
                File.WriteAllText(Path.Combine(dir, "grid.json"), PatchGridJson.Write(grid));
            }

            // Drawn with a uniform factor so every run draws the same vertices (timings comparable).
            var range = TerrainRange.full;
            var tess = new TessellationSettings(a.Int("tiles", 16), 64f, 8f, (float)a.Double("factor", 32));
            var noiseSettings = new NoiseSettings(noise ? (float)a.Double("noise-amplitude", 0.0015) : 0f, 24f, 2f, 2f, 5);
            var colors = new HeightColorSettings(0.3f, 0.1f, 24f);
            TerrainParams p = TerrainParams.Create(grid, range, RangeOrigin.zero, tess, noiseSettings, colors,
                new Float3(0.20f, 0.30f, 0.12f), new Float3(0.55f, 0.50f, 0.42f));
            string scene = Path.Combine(dir, "scene");
            Directory.CreateDirectory(scene);
            BufferFiles.Write(Path.Combine(scene, "control_points.f32"), GpuLayout.PackControlPoints(grid));
            BufferFiles.Write(Path.Combine(scene, "regions.f32"), GpuLayout.PackRegions(grid));
            BufferFiles.Write(Path.Combine(scene, "grid_lines.f32"), GpuLayout.PackGridLines(grid));
            BufferFiles.Write(Path.Combine(scene, "params.f32"), p.Pack());
            BufferFiles.Write(Path.Combine(scene, "camera.f32"), Camera(a, width, height).Pack());

            SnowSettings snow = Settings(a);
            var keywords = noise ? TerrainKeywords.Noise : TerrainKeywords.None;
            TerrainInputs inputs = TerrainInputs.Create(grid, p);
            foreach (int r in resolutions)
            {
                snow.resolution = r;
                snow.Validate();
                BufferFiles.Write(Path.Combine(dir, $"field_params_{r}.f32"), SnowFieldTerrain.ParamsFor(p, r).Pack());
                BufferFiles.Write(Path.Combine(dir, $"snow_params_{r}.f32"), snow.Params(dt).Pack());
                Float4 size = SnowMap.PackMapSize(r, snow.depthCap);
                BufferFiles.Write(Path.Combine(dir, $"snow_size_{r}.f32"), new[] { size.x, size.y, size.z, size.w });
                if (cpu)
                {
                    var field = new SnowField(r);
                    SnowFieldTerrain.Evaluate(inputs, field, keywords);
                    var sim = new SnowSimulation(snow);
                    for (int n = 0; n < steps; n++) sim.Step(field, dt);
                    BufferFiles.Write(Path.Combine(dir, $"cpu_depth_{r}.f32"), sim.Depth);
                    BufferFiles.Write(Path.Combine(dir, $"cpu_field_{r}.f32"), field.Data);
                }
            }
            File.WriteAllText(Path.Combine(dir, "run.txt"), string.Join("\n",
                "resolutions " + string.Join(" ", resolutions), FormattableString.Invariant($"steps {steps}"),
                FormattableString.Invariant($"dt {dt:R}"), FormattableString.Invariant($"cap {snow.depthCap:R}"),
                "noise " + (noise ? 1 : 0), FormattableString.Invariant($"patches {tess.tiles * tess.tiles}"),
                FormattableString.Invariant($"size {width} {height}"), ""));
            Console.WriteLine(FormattableString.Invariant(
                $"snow scene {grid.Columns}x{grid.Rows} patches, R {string.Join(",", resolutions)}, {steps} steps of {dt:R} s, wind {snow.wind}{(cpu ? ", CPU depth" : "")} -> {dir}"));
            return 0;
        }

        /// <summary>The snowfall of the pictures and the bench: wind along +x, twice the fall speed (fall line 27 degrees).</summary>
        static SnowSettings Settings(Args a)
        {
            var s = SnowSettings.Default;
            var w = a.Doubles("wind", 2, "2,0");
            s.wind = new Float2((float)w[0], (float)w[1]);
            s.scale = (float)a.Double("scale", 0.002);
            s.depthCap = (float)a.Double("cap", 0.02);
            s.rayLength = 0.3f;
            s.raySteps = 32;
            return s;
        }

        /// <summary>
        /// A ridge running along y at x = 0.5 (0.16 high, steep enough that its lee face is steeper
        /// than the 45 degree fall line) on gently rolling ground, with a low second ridge upwind.
        /// </summary>
        public static double[] RidgeHeightmap(int samples)
        {
            var h = new double[samples * samples];
            for (int j = 0; j < samples; j++)
                for (int i = 0; i < samples; i++)
                {
                    double x = i / (samples - 1.0), y = j / (samples - 1.0);
                    double crest = 0.5 + 0.04 * Math.Sin(2 * Math.PI * y);
                    double ridge = 0.16 * Math.Exp(-Math.Pow((x - crest) / 0.09, 2)) * (0.8 + 0.2 * Math.Cos(3 * y));
                    double low = 0.04 * Math.Exp(-Math.Pow((x - 0.18) / 0.05, 2));
                    double roll = 0.01 * Math.Sin(5 * x + 1) * Math.Cos(4 * y);
                    h[j * samples + i] = ridge + low + roll;
                }
            return h;
        }

        /// <summary>
        /// Looking south along the ridge from above its north end (--eye, --target in world units):
        /// the windward (west) face on the left, the lee (east) face on the right. World is the
        /// terrain centred on the origin, Y up, heights times --height-scale (1.5) for the view.
        /// </summary>
        static RigCamera Camera(Args a, int width, int height)
        {
            double hs = a.Double("height-scale", 1.5);
            var eye = a.Doubles("eye", 3, "0.05,0.9,0.8");
            var target = a.Doubles("target", 3, "0,0,-0.2");
            // object (x, z, y) -> world ((x - 0.5), hs z, (y - 0.5))
            var objectToWorld = new double[,] { { 1, 0, 0, -0.5 }, { 0, hs, 0, 0 }, { 0, 0, 1, -0.5 }, { 0, 0, 0, 1 } };
            var cam = RigCamera.LookAt(eye, target, a.Double("fov", 45), width, height, 0.01, 10, objectToWorld);
            cam.LightDirection = a.Doubles("light", 3, "-0.5,0.8,0.2");
            return cam;
        }
    }
}
