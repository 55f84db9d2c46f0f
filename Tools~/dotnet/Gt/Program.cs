using System;
using System.Collections.Generic;

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
        }

        static readonly Dictionary<string, Command> Commands = new Dictionary<string, Command>(StringComparer.Ordinal);

        /// <summary>Options RigScene.FromArgs reads (every command that draws a scene takes them).</summary>
        const string SceneOptions = "grid range plain-origin tiles max-factor target-pixels factor noise octaves gamma noise-vertices anchor-at width height";

        static int Main(string[] argv)
        {
            Register();
            if (argv.Length == 0 || !Commands.TryGetValue(argv[0], out var cmd))
            {
                if (argv.Length > 0)
                {
                    Console.Error.WriteLine($"gt-cli: unknown command '{InputLimits.Quote(argv[0])}' (commands: {string.Join(", ", Commands.Keys)}; gt-cli alone lists them)");
                    return ExitUsage;
                }
                Console.Error.WriteLine("usage: gt-cli COMMAND [options]");
                foreach (var kv in Commands) Console.Error.WriteLine($"  {kv.Key,-12} {kv.Value.Help}");
                return 0;
            }
            try
            {
                return cmd.Run(new Args(argv, 1, cmd.Options));
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

        static void Add(string name, string help, Func<Args, int> run, string options) =>
            Commands[name] = new Command
            {
                Help = help, Run = run,
                Options = new HashSet<string>(options.Split(new[] { ' ' }, StringSplitOptions.RemoveEmptyEntries), StringComparer.Ordinal),
            };

        static void Register()
        {
            Add("check", "validate a grid file and list geometry warnings (--grid FILE); exit 1 if invalid", CheckCommand.Run, "grid");
            Add("demo-grid", "build the 5x5 sample grid fitted to a procedural heightmap, or with --dem FILE to an SRTM crop (--out FILE)", DemoGridCommand.Run, "out columns rows samples dem metres-across exaggerate");
            Add("eval", "Core float, Core double and (--gpu) GPU position and normal at points (--grid FILE --points \"x,y;...\")", EvalCommand.Run,
                "grid device gpu harness no-noise noise octaves pass-state points points-file span spirv");
            Add("unity-asset", "write a grid JSON as the YAML of a PatchGridAsset in blocks (--grid FILE --out FILE.asset --script-guid GUID --block-script-guid GUID [--name NAME])", UnityAssetCommand.Run,
                "block-script-guid grid name out script-guid");
            Add("error", "error of the drawn triangles against the exact surface (scene options; --factors FILE or --factor F)", ErrorCommand.Run,
                SceneOptions + " factors max-cells paper print-factors tile-factors vertex-cache with-noise write-tile-factors");
            Add("bench-plan", "write the buffers and the job list of gt bench (--grid FILE --out DIR [--quick])", BenchPlan.Run, "grid frames height out quick warmup width");
            Add("bench-report", "tables of a gt bench run (--plan DIR --raw DIR --grid FILE)", BenchReport.Run, "grid plan raw tsv");
            Add("bench-docs", "rewrite the summary tables of a performance page from a run's full table (--table bench_table.md --page performance.md)", a => BenchDocs.Run(a.String("table"), a.String("page")), "page table");
            Add("lod-scene", "write a ground-level levels-of-detail view for the harness: buffers and --params-tail (--out DIR)", LodSceneCommand.Run,
                "out grid terrain-m eye-m finest-m tiles factor target-pixels segment-pixels width height ground no-origin factors max-cells relief-m per-level");
            Add("snow-scene", "write a snow run's inputs: ridge grid, harness buffers, field/snow params per R (--out DIR [--cpu])", SnowSceneCommand.Run,
                "cap cpu dt eye factor fov grid height height-scale light no-noise noise-amplitude out patches resolutions scale steps target tiles width wind");
            Add("pack", "write the harness's buffer files for one scene (--grid FILE --out DIR ...)", PackCommand.Run, SceneOptions + " orbit out noise-table");
            Add("estimate", "CPU time of the inspector's triangle estimate, and its sample against every tile (--grid FILE [--tiles 16,32,64] [--target PX] [--repeat N])", EstimateCommand.Run,
                "grid repeat target tiles");
            Add("fit-bench", "one heightmap fit's error, G1 angle, time and memory (--dem FILE.hgt | --size N) --patches P [--c1 | --legacy | --ls]", FitBenchCommand.Run,
                "c1 dem legacy ls patches size");
            Add("fit-reference", "best smooth approximations with the Gregory net's unknown count against the bilinear baseline (--dem FILE.hgt --patches P)", FitReferenceCommand.Run,
                "dem patches crop");
            Add("query-bench", "CPU height/normal/ray queries per second (1 and N threads) and the collider patch's cost and deviation (--grid FILE [--size M] [--threads N])", QueryBenchCommand.Run,
                "collider-samples collider-spacing grid no-noise octaves seconds size threads");
            Add("sculpt-bench", "CPU cost of one sculpt dab before and after issue 36, the whole-grid check, and the bytes a whole-grid step records for Undo (--patches N [--dabs D] [--radius-patches R])", SculptBenchCommand.Run,
                "dabs patches radius-patches");
            Add("jitter", "deep-zoom vertex jitter table, plain vs shipped float path (--widths 1e-2,1e-4,1e-6 ...)", JitterCommand.Run,
                "center factor grid noise octaves pan pixels tiles widths");
        }
    }
}
