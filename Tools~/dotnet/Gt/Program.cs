using System;
using System.Collections.Generic;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// The rig's C# front end. Each command is a thin layer over Core; the shell scripts in
    /// Tools~/rig call it. Usage: gt-cli COMMAND [--option value ...]
    /// </summary>
    static class Program
    {
        static readonly Dictionary<string, (string help, Func<Args, int> run)> Commands =
            new Dictionary<string, (string, Func<Args, int>)>(StringComparer.Ordinal);

        static int Main(string[] argv)
        {
            Register();
            if (argv.Length == 0 || !Commands.TryGetValue(argv[0], out var cmd))
            {
                Console.Error.WriteLine("usage: gt-cli COMMAND [options]");
                foreach (var kv in Commands) Console.Error.WriteLine($"  {kv.Key,-12} {kv.Value.help}");
                return argv.Length == 0 ? 0 : 2;
            }
            try
            {
                return cmd.run(new Args(argv, 1));
            }
            catch (Exception e) when (e is ArgumentException || e is FormatException || e is System.IO.IOException)
            {
                Console.Error.WriteLine($"gt-cli {argv[0]}: {e.Message}");
                return 1;
            }
        }

        static void Register()
        {
            Commands["demo-grid"] = ("build the 5x5 sample grid fitted to a procedural heightmap (--out FILE)", DemoGridCommand.Run);
            Commands["eval"] = ("Core float, Core double and (--gpu) GPU position and normal at points (--grid FILE --points \"x,y;...\")", EvalCommand.Run);
            Commands["unity-asset"] = ("write a grid JSON as the YAML of a PatchGridAsset (--grid FILE --out FILE.asset --script-guid GUID [--name NAME])", UnityAssetCommand.Run);
            Commands["error"] = ("error of the drawn triangles against the exact surface (scene options; --factors FILE or --factor F)", ErrorCommand.Run);
            Commands["bench-plan"] = ("write the buffers and the job list of gt bench (--grid FILE --out DIR [--quick])", BenchPlan.Run);
            Commands["bench-report"] = ("tables of a gt bench run (--plan DIR --raw DIR --grid FILE)", BenchReport.Run);
            Commands["snow-scene"] = ("write a snow run's inputs: ridge grid, harness buffers, field/snow params per R (--out DIR [--cpu])", SnowSceneCommand.Run);
            Commands["pack"] = ("write the harness's buffer files for one scene (--grid FILE --out DIR ...)", PackCommand.Run);
            Commands["estimate"] = ("CPU time of the inspector's triangle estimate, and its sample against every tile (--grid FILE [--tiles 16,32,64] [--target PX] [--repeat N])", EstimateCommand.Run);
            Commands["query-bench"] = ("CPU height/normal/ray queries per second (1 and N threads) and the collider patch's cost and deviation (--grid FILE [--size M] [--threads N])", QueryBenchCommand.Run);
            Commands["jitter"] = ("deep-zoom vertex jitter table, plain vs shipped float path (--widths 1e-2,1e-4,1e-6 ...)", JitterCommand.Run);
        }
    }
}
