using System;
using System.Collections.Generic;
using System.Linq;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// The rig's C# front end. Each command is a thin layer over Core; the shell scripts in
    /// Tools~/rig call it. Usage: gt-cli COMMAND [--option value ...]. Exit codes: 0 done, 1 bad data
    /// (a file or value Core refuses, a missing or unreadable file), 2 bad usage (unknown command or
    /// option, malformed number), 3 an internal error (a bug: set GT_DEBUG=1 for its stack trace).
    /// </summary>
    static class Program
    {
        public const int ExitBadData = 1, ExitUsage = 2, ExitInternal = 3;

        sealed class Command
        {
            public string Help;
            public Func<Args, int> Run;
            public HashSet<string> Options;
            public Dictionary<string, NumericOption> Numbers;
        }

        static readonly Dictionary<string, Command> Commands = new Dictionary<string, Command>(StringComparer.Ordinal);

        // The ranges numeric options accept (Args checks each before the command runs). Shared ones:
        /// <summary>Vulkan's and D3D11's largest framebuffer side (maxFramebufferWidth of lavapipe and of the H200).</summary>
        const int MaxPixels = 16384;
        /// <summary>Frames or steps of one run: 100,000 frames of 1080p are minutes on a GPU, hours on lavapipe.</summary>
        const int MaxFrames = 100000;
        /// <summary>Metres across a terrain: the Earth's circumference is 4e7.</summary>
        const double MaxMetres = 1e8;
        static readonly NumericOption Width = NumericOption.Int("width", 1, MaxPixels), Height = NumericOption.Int("height", 1, MaxPixels);
        /// <summary>M x M tiles: GregoryTerrainRenderer.Tiles clamps to 1..64.</summary>
        static readonly NumericOption Tiles = NumericOption.Int("tiles", 1, 64);
        /// <summary>A drawn scene's tiles: TessellationSettings.Validate's 1..1024 (gt bench draws up to 256 beside static meshes).</summary>
        static readonly NumericOption SceneTiles = NumericOption.Int("tiles", 1, 1024);
        static readonly NumericOption TargetPixels = NumericOption.Above("target-pixels", 0, MaxPixels);
        static readonly NumericOption Octaves = NumericOption.Int("octaves", 0, NoiseSettings.MaxOctaves);
        /// <summary>amplitude (terrain units; the terrain is 1 across), frequency (cells across: the finest octave stays below 2^24, NoiseSettings), alpha &gt; 1, beta &gt; 0.</summary>
        static readonly NumericOption Noise = NumericOption.Numbers("noise", Bounds.Real(-1000, 1000, "amplitude"),
            Bounds.Above(0, 1 << 24, "frequency"), Bounds.Above(1, 1024, "alpha"), Bounds.Above(0, 1024, "beta"));
        static readonly NumericOption MaxCells = NumericOption.Int("max-cells", 1, 1 << 26);

        /// <summary>Options RigScene.FromArgs reads (every command that draws a scene takes them).</summary>
        const string SceneOptions = "grid plain-origin";
        static readonly NumericOption[] SceneNumbers =
        {
            UnitSquareRange("range"), UnitSquareRange("anchor-at"),
            SceneTiles, NumericOption.Real("max-factor", 1, TessellationSettings.HardwareMaxFactor), TargetPixels,
            NumericOption.Real("factor", 0, TessellationSettings.HardwareMaxFactor),   // 0: adaptive (Core refuses 0 < F < 1)
            Noise, Octaves, NumericOption.One("gamma", new Bounds { Min = -1000, Max = 1000, NotZero = true }),
            NumericOption.Real("noise-vertices", 0, 1 << 24), Width, Height,
        };

        /// <summary>c,d,g,h in the unit square (TerrainRange.Validate refuses an empty or mirrored one).</summary>
        static NumericOption UnitSquareRange(string name) =>
            NumericOption.Numbers(name, Bounds.Real(0, 1, "c"), Bounds.Real(0, 1, "d"), Bounds.Real(0, 1, "g"), Bounds.Real(0, 1, "h"));

        static int Main(string[] argv)
        {
            Register();
            if (argv.Length > 0 && argv[0] == "help")
            {
                if (argv.Length == 1) argv = new string[0];   // the list of commands
                else if (argv.Length == 2 && Commands.TryGetValue(argv[1], out var described)) return Describe(argv[1], described);
                else
                {
                    Console.Error.WriteLine($"gt-cli help: '{InputLimits.Quote(string.Join(" ", argv, 1, argv.Length - 1))}' is not a command (gt-cli help COMMAND)");
                    return ExitUsage;
                }
            }
            if (argv.Length == 0 || !Commands.TryGetValue(argv[0], out var cmd))
            {
                if (argv.Length > 0)
                {
                    Console.Error.WriteLine($"gt-cli: unknown command '{InputLimits.Quote(argv[0])}' (commands: {string.Join(", ", Commands.Keys)}; gt-cli alone lists them)");
                    return ExitUsage;
                }
                Console.Error.WriteLine("usage: gt-cli COMMAND [options]");
                foreach (var kv in Commands) Console.Error.WriteLine($"  {kv.Key,-12} {kv.Value.Help}");
                Console.Error.WriteLine("gt-cli help COMMAND lists a command's options and the ranges of its numbers.");
                return 0;
            }
            try
            {
                return cmd.Run(new Args(argv, 1, cmd.Options, cmd.Numbers));
            }
            catch (UsageException e)
            {
                Console.Error.WriteLine($"gt-cli {argv[0]}: {e.Message}");
                return ExitUsage;
            }
            catch (Exception e) when (e is ArgumentException || e is FormatException || e is System.IO.IOException
                                      || e is UnauthorizedAccessException || e is OperationCanceledException)
            {
                Console.Error.WriteLine($"gt-cli {argv[0]}: {Message(e)}");
                return ExitBadData;
            }
            catch (Exception e) when (Environment.GetEnvironmentVariable("GT_DEBUG") != "1")
            {
                Console.Error.WriteLine($"gt-cli {argv[0]}: internal error ({e.GetType().Name}): {InputLimits.Quote(e.Message)} (set GT_DEBUG=1 for the stack trace)");
                return ExitInternal;
            }
        }

        /// <summary>The message without .NET's " (Parameter 'x')" suffix: the text already names the field.</summary>
        static string Message(Exception e) =>
            e is ArgumentException a && a.ParamName != null ? a.Message.Replace($" (Parameter '{a.ParamName}')", "") : e.Message;

        /// <summary>gt-cli help COMMAND: one line per option, a numeric one with its range ("--tiles N (1..64)").</summary>
        static int Describe(string name, Command c)
        {
            Console.WriteLine($"gt-cli {name}: {c.Help}");
            var lines = new List<string>();
            foreach (string o in c.Options) lines.Add("  --" + o);
            foreach (var n in c.Numbers.Values) lines.Add($"  --{n.Name} {n.Text}");
            lines.Sort(StringComparer.Ordinal);
            foreach (string l in lines) Console.WriteLine(l);
            return 0;
        }

        /// <param name="options">The command's other options (files, names, flags), space-separated.</param>
        /// <param name="numbers">Its numeric options with the ranges they accept.</param>
        static void Add(string name, string help, Func<Args, int> run, string options, params NumericOption[] numbers)
        {
            var c = new Command
            {
                Help = help, Run = run,
                Options = new HashSet<string>(options.Split(new[] { ' ' }, StringSplitOptions.RemoveEmptyEntries), StringComparer.Ordinal),
                Numbers = new Dictionary<string, NumericOption>(StringComparer.Ordinal),
            };
            foreach (NumericOption n in numbers)
                if (!c.Numbers.TryAdd(n.Name, n) || c.Options.Contains(n.Name))
                    throw new InvalidOperationException($"gt-cli {name}: --{n.Name} is declared twice");
            Commands[name] = c;
        }

        static NumericOption[] Scene(params NumericOption[] more) => SceneNumbers.Concat(more).ToArray();

        /// <summary>Args over the scene options alone, for a scene a command builds itself (BenchPlan.Scene): checked as a user's.</summary>
        internal static Args SceneArgs(string[] argv) =>
            new Args(argv, 0, SceneOptions.Split(' '), SceneNumbers.ToDictionary(n => n.Name, StringComparer.Ordinal));

        static void Register()
        {
            static NumericOption Xyz(string name) => NumericOption.Numbers(name, Bounds.Real(-1000, 1000, "x"), Bounds.Real(-1000, 1000, "y"), Bounds.Real(-1000, 1000, "z"));
            NumericOption frames = NumericOption.Int("frames", 1, MaxFrames);
            // Patches a side of a fitted grid: 1024 x 1024 is a million patches, 480 MB of control points.
            NumericOption patches = NumericOption.Int("patches", 1, 1024);
            // Heightmap samples a side: 16384^2 doubles are 2 GiB.
            NumericOption size = NumericOption.Int("size", 2, 16384);

            Add("generate", "write the generated side of each GPU contract Core declares with [GenerateHlsl] (--root PACKAGE_DIR)", a => ContractGenerator.Run(a.String("root")), "root");
            Add("mirror", "pair each HLSL file with its Core twin and fail on a function on one side only, a different parameter shape or a keyword switched at runtime (--root PACKAGE_DIR)", a => MirrorCheck.Run(a.String("root")), "root");
            Add("check", "validate a grid file and list geometry warnings (--grid FILE); exit 1 if invalid", CheckCommand.Run, "grid");
            Add("demo-grid", "build the 5x5 sample grid fitted to a procedural heightmap, or with --dem FILE to an SRTM crop (--out FILE)", DemoGridCommand.Run, "out dem",
                NumericOption.Int("columns", 1, 1024), NumericOption.Int("rows", 1, 1024), NumericOption.Int("samples", 2, 16384),
                NumericOption.Above("metres-across", 0, MaxMetres), NumericOption.Above("exaggerate", 0, 1000));
            Add("eval", "Core float, Core double and (--gpu) GPU position and normal at points (--grid FILE --points \"x,y;...\")", EvalCommand.Run,
                "grid device gpu harness no-noise pass-state points points-file spirv",
                Noise, Octaves, NumericOption.Above("span", 0, 0.5));   // span: the point's tile, which must fit beside it in the unit square
            Add("unity-asset", "write a grid JSON as the YAML of a PatchGridAsset in blocks (--grid FILE --out FILE.asset --script-guid GUID --block-script-guid GUID [--name NAME])", UnityAssetCommand.Run,
                "block-script-guid grid name out script-guid");
            Add("error", "error of the drawn triangles against the exact surface (scene options; --factors FILE or --factor F)", ErrorCommand.Run,
                SceneOptions + " factors paper print-factors tile-factors vertex-cache with-noise write-tile-factors", Scene(MaxCells));
            Add("bench-plan", "write the buffers and the job list of gt bench (--grid FILE --out DIR [--quick])", BenchPlan.Run, "grid out quick",
                Width, Height, frames, NumericOption.Int("warmup", 0, MaxFrames));
            Add("bench-report", "tables of a gt bench run (--plan DIR --raw DIR --grid FILE)", BenchReport.Run, "grid plan raw tsv");
            Add("bench-docs", "rewrite the summary tables of a performance page from a run's full table (--table bench_table.md --page performance.md)", a => BenchDocs.Run(a.String("table"), a.String("page")), "page table");
            Add("lod-scene", "write a ground-level levels-of-detail view for the harness: buffers and --params-tail (--out DIR)", LodSceneCommand.Run,
                "out grid no-origin no-plain factors per-level",
                NumericOption.Above("terrain-m", 0, MaxMetres), NumericOption.Above("eye-m", 0, MaxMetres), NumericOption.Above("finest-m", 0, MaxMetres),
                NumericOption.Int("tiles", 2, 64), NumericOption.Int("factor", 0, 64), TargetPixels, NumericOption.Above("segment-pixels", 0, MaxPixels),
                Width, Height, NumericOption.Numbers("ground", Bounds.Real(0, 1, "x"), Bounds.Real(0, 1, "y")), MaxCells,
                NumericOption.Real("relief-m", 0, MaxMetres));   // relief-m 0: the grid stretched to --terrain-m
            Add("lod-cpu-bench", "the Horizon levels' CPU work a frame per camera: microseconds, bytes allocated, bytes sent (prints; asserts nothing)", LodCpuBenchCommand.Run,
                "", NumericOption.Int("frames", 1, 100000000), NumericOption.Int("rounds", 1, 1000));
            Add("lod-cache-churn", "what a clipmap-style vertex cache of the Horizon levels would evaluate again a frame along the bench's walking and flying paths (prints; asserts nothing)",
                LodCacheChurnCommand.Run, "", NumericOption.Int("frames", 1, 100000));
            Add("snow-scene", "write a snow run's inputs: ridge grid, harness buffers, field/snow params per R (--out DIR [--cpu])", SnowSceneCommand.Run,
                "cpu grid no-noise out",
                NumericOption.Above("cap", 0, 1000), NumericOption.Above("dt", 0, 3600), Xyz("eye"), NumericOption.Real("factor", 0, TessellationSettings.HardwareMaxFactor),
                NumericOption.Above("fov", 0, 179), Height, NumericOption.Above("height-scale", 0, 1000), Xyz("light"),
                NumericOption.Real("noise-amplitude", -1000, 1000), NumericOption.Int("patches", 1, 64),
                NumericOption.ListOf("resolutions", Bounds.Int(64, 4096)),   // SnowSettings: powers of two from 64 to 4096
                NumericOption.Real("scale", 0, 1000), NumericOption.Int("steps", 1, MaxFrames), Xyz("target"), Tiles, Width,
                NumericOption.Numbers("wind", Bounds.Real(-1000, 1000, "x"), Bounds.Real(-1000, 1000, "y")));
            Add("pack", "write the harness's buffer files for one scene (--grid FILE --out DIR ...)", PackCommand.Run, SceneOptions + " out noise-table",
                Scene(NumericOption.Numbers("orbit", Bounds.Int(1, MaxFrames, "frames"), Bounds.Real(-90, 90, "degrees"))));
            Add("estimate", "CPU time of the inspector's triangle estimate, and its sample against every tile (--grid FILE [--tiles 16,32,64] [--target PX] [--repeat N])", EstimateCommand.Run,
                "grid", NumericOption.Int("repeat", 1, MaxFrames), NumericOption.Above("target", 0, MaxPixels), NumericOption.ListOf("tiles", Bounds.Int(1, 64)));
            Add("fit-bench", "one heightmap fit's error, G1 angle, time and memory (--dem FILE.hgt | --size N) --patches P [--c1 | --legacy | --ls]", FitBenchCommand.Run,
                "c1 dem legacy ls", patches, size);
            Add("fit-reference", "best smooth approximations with the Gregory net's unknown count against the bilinear baseline (--dem FILE.hgt --patches P)", FitReferenceCommand.Run,
                "dem", patches, NumericOption.Int("crop", 0, 16384));   // crop 0: the whole tile
            Add("query-bench", "CPU height/normal/ray queries per second (1 and N threads) and the collider patch's cost and deviation (--grid FILE [--size M] [--threads N])", QueryBenchCommand.Run,
                "grid no-noise",
                NumericOption.Int("collider-samples", 2, 255),   // GregoryTerrainCollider's samples range
                NumericOption.Above("collider-spacing", 0, MaxMetres), Noise, Octaves, NumericOption.Above("seconds", 0, 3600),
                NumericOption.Above("size", 0, MaxMetres), NumericOption.Int("threads", 1, 1024));
            Add("sculpt-bench", "CPU cost of one sculpt dab before and after issue 36, the whole-grid check, and the bytes a whole-grid step records for Undo (--patches N [--dabs D] [--radius-patches R])", SculptBenchCommand.Run,
                "", NumericOption.Int("dabs", 1, MaxFrames), NumericOption.Int("patches", 2, 1024), NumericOption.Above("radius-patches", 0, 1024));
            Add("jitter", "deep-zoom vertex jitter table, plain vs shipped float path (--widths 1e-2,1e-4,1e-6 ...)", JitterCommand.Run,
                "grid", NumericOption.Numbers("center", Bounds.Real(0, 1, "x"), Bounds.Real(0, 1, "y")), NumericOption.Int("factor", 1, 64), Noise, Octaves,
                NumericOption.Real("pan", -MaxPixels, MaxPixels), NumericOption.Above("pixels", 0, MaxPixels), Tiles,
                NumericOption.ListOf("widths", Bounds.Above(0, 1)));   // range widths in the unit square
        }
    }
}
