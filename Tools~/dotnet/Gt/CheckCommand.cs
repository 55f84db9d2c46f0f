using System;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// gt-cli check --grid FILE: reads and validates a grid (every rule the GPU needs) and lists the
    /// geometry warnings (PatchGridGeometry): exit 0 when valid (warnings or not), 1 when not.
    /// </summary>
    static class CheckCommand
    {
        public static int Run(Args a)
        {
            string path = a.String("grid");
            var watch = System.Diagnostics.Stopwatch.StartNew();
            PatchGrid grid = PatchGridJson.ReadFile(path);
            double read = watch.Elapsed.TotalSeconds;
            var warnings = PatchGridGeometry.Warnings(grid);
            foreach (string w in warnings) Console.WriteLine("warning: " + w);
            Console.WriteLine(FormattableString.Invariant(
                $"valid grid: {grid.Columns} x {grid.Rows} = {grid.PatchCount} patches, {warnings.Count} warning line(s) -> {InputLimits.Quote(path)} (read and validated in {read:F2} s, warnings in {watch.Elapsed.TotalSeconds - read:F2} s)"));
            return 0;
        }
    }
}
