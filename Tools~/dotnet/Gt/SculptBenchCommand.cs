using System;
using System.Diagnostics;
using System.Linq;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// gt-cli sculpt-bench: the CPU cost of one sculpt dab on an n x n grid, as the editor paid it per
    /// dab before issue 36 and as it pays it now, and what a whole-grid replacement records for Undo.
    /// A benchmark, not a test: it prints, it asserts nothing.
    /// <para>"Before" replays the Core calls the old code made per dab: the asset's ApplyEdit hashed
    /// every block; the renderer's upload converted and validated the grid (ToPatchGrid: the serialized
    /// check, then a second conversion), packed it (validating again) and read its height range
    /// (checking it once more); the query converted and validated it (ToPatchGrid) and was built anew
    /// (validating again). "After" makes the calls the code makes now: the blocks the dab wrote are
    /// hashed again, the renderer and the query each catch up on the changed patches
    /// (PatchChangeLog.Update: read and checked on those patches and their edges), the renderer packs
    /// and uploads those records, and the query is widened by them (WithPatches). The brush itself
    /// (PatchBrush.Apply, the same before and after) is timed apart. GPU upload time is not measured.</para>
    /// </summary>
    static class SculptBenchCommand
    {
        public static int Run(Args a)
        {
            int n = a.Int("patches", 256);
            int dabs = a.Int("dabs", 20);
            double radiusPatches = a.Double("radius-patches", 2.0);
            var noise = new NoiseSettings(0.004f, 16f, 2f, 2f, 8);
            PatchGrid grid = PatchGrid.CreateFlat(n, n);
            Console.WriteLine(FormattableString.Invariant(
                $"# sculpt dabs on {n} x {n} patches ({n * n} patches, {PatchGridBlocks.BlockCount(n * n)} blocks), brush radius {radiusPatches} patches, {dabs} dabs"));

            // The asset's data, the sculpt tool's copy, the renderer's and the query's grids.
            double[][] blocks = PatchGridBlocks.FromGrid(grid);
            PatchGrid stroke = grid.Clone();
            var log = new PatchChangeLog();
            int version = 1;
            log.Restart(version, grid.PatchCount);
            ulong[] hashes = PatchGridBlocks.BlockHashes(blocks);
            PatchGrid uploaded = ToPatchGridNow(blocks, grid);
            var query = new TerrainSurfaceQuery(ToPatchGridNow(blocks, grid), noise);
            int uploadedVersion = version, queryVersion = version;

            double brushMs = 0, beforeMs = 0, afterMs = 0;
            long changedPatches = 0;
            var rng = new Random(1);
            for (int d = 0; d < dabs; d++)
            {
                var dab = new BrushDab(BrushMode.Raise, 0.1 + 0.8 * rng.NextDouble(), 0.1 + 0.8 * rng.NextDouble(), radiusPatches / n, 0.001);
                var sw = Stopwatch.StartNew();
                PatchEdit edit = PatchBrush.Apply(stroke, dab);
                edit.ApplyTo(stroke);
                brushMs += sw.Elapsed.TotalMilliseconds;
                changedPatches += edit.Patches.Length;
                for (int k = 0; k < edit.Patches.Length; k++) PatchGridBlocks.SetPatch(blocks, edit.Patches[k], edit.Values[k]);

                sw.Restart();
                OldDab(blocks, grid, noise);
                beforeMs += sw.Elapsed.TotalMilliseconds;

                sw.Restart();
                version++;
                PatchGridBlocks.Rehash(hashes, blocks, edit.Patches);
                PatchGridBlocks.Combine(0, hashes);
                log.Add(version, edit.Patches);
                PatchGrid g = log.Update(uploaded, uploadedVersion, blocks, out int[] changed) ?? throw new InvalidOperationException("the log lost the dab");
                var records = new GregoryPatchRecord[changed.Length];
                for (int k = 0; k < changed.Length; k++) records[k] = GpuLayout.PackPatchRecord(g.Patches[changed[k]]);
                uploaded = g; uploadedVersion = version;
                PatchGrid q = log.Update(query.Grid, queryVersion, blocks, out changed) ?? throw new InvalidOperationException("the log lost the dab");
                query = query.WithPatches(q, changed); queryVersion = version;
                afterMs += sw.Elapsed.TotalMilliseconds;
            }
            Console.WriteLine(FormattableString.Invariant($"patches changed per dab (mean)      {(double)changedPatches / dabs,10:F1}"));
            Console.WriteLine(FormattableString.Invariant($"brush (PatchBrush, both)    ms/dab  {brushMs / dabs,10:F3}"));
            Console.WriteLine(FormattableString.Invariant($"before: asset+upload+query  ms/dab  {beforeMs / dabs,10:F3}"));
            Console.WriteLine(FormattableString.Invariant($"after:  asset+upload+query  ms/dab  {afterMs / dabs,10:F3}"));
            Console.WriteLine(FormattableString.Invariant($"speed-up of the asset, upload and query work: {beforeMs / afterMs:F0}x"));

            // A grid's first read after a load or domain reload: the whole-grid check, once, against the
            // fingerprint an undo compares.
            var t = Stopwatch.StartNew();
            CheckSerialized(blocks, grid);
            double checkMs = t.Elapsed.TotalMilliseconds;
            t.Restart();
            PatchGridBlocks.Combine(0, PatchGridBlocks.BlockHashes(blocks));
            double hashMs = t.Elapsed.TotalMilliseconds;
            Console.WriteLine(FormattableString.Invariant($"whole-grid check (convert + validate)   ms  {checkMs,10:F1}   (before: at every load in OnEnable, and again in each ToPatchGrid and GetHeightRange)"));
            Console.WriteLine(FormattableString.Invariant($"fingerprint (every block hashed)       ms  {hashMs,10:F1}"));

            UndoBytes(n);
            return 0;
        }

        /// <summary>The Core work of one dab before issue 36 (see the class summary), on the asset's blocks.</summary>
        static void OldDab(double[][] blocks, PatchGrid shape, NoiseSettings noise)
        {
            PatchGridBlocks.Fingerprint(blocks, 0);                               // ApplyEdit
            PatchGrid upload = OldToPatchGrid(blocks, shape);                     // EnsureUploaded: ToPatchGrid
            GpuLayout.PackPatchRecords(upload);                                    // packs, validating
            CheckSerialized(blocks, shape);                                        // GetHeightRange
            new TerrainSurfaceQuery(OldToPatchGrid(blocks, shape), noise);          // SurfaceQuery: ToPatchGrid, then the query (validating)
        }

        static PatchGrid OldToPatchGrid(double[][] blocks, PatchGrid shape)
        {
            CheckSerialized(blocks, shape);
            return ToPatchGridNow(blocks, shape);
        }

        /// <summary>PatchGridAsset.CheckSerializedData on blocks: shape, then the whole grid converted and validated.</summary>
        static void CheckSerialized(double[][] blocks, PatchGrid shape)
        {
            string e = PatchGridBlocks.CheckShape(blocks, shape.PatchCount);
            if (e != null) throw new ArgumentException(e);
            GpuLayout.CheckSize(shape.Columns, shape.Rows);
            new PatchGrid(shape.Columns, shape.Rows, shape.XLines, shape.YLines, PatchGridBlocks.ToPatches(blocks, shape.PatchCount)).Validate();
        }

        static PatchGrid ToPatchGridNow(double[][] blocks, PatchGrid shape) =>
            new PatchGrid(shape.Columns, shape.Rows, (double[])shape.XLines.Clone(), (double[])shape.YLines.Clone(), PatchGridBlocks.ToPatches(blocks, shape.PatchCount));

        /// <summary>
        /// What PatchGridAssetUndo.SetGrid records per whole-grid step, in bytes of control points: before,
        /// every block; now, the blocks whose bits change (PatchGridBlocks.ChangedBlocks), measured on an
        /// m x m grid and scaled to 1024 x 1024 (the window's largest): by the block count for a change
        /// over the whole grid, as is for a local one.
        /// </summary>
        static void UndoBytes(int n)
        {
            int m = Math.Min(n, 128);
            PatchGrid flat = PatchGrid.CreateFlat(m, m);
            double[][] current = PatchGridBlocks.FromGrid(flat);
            int blocks = current.Length, large = PatchGridBlocks.BlockCount(1024 * 1024);
            PatchGrid g1 = flat.Clone();
            G1Builder.MakeG1(g1);
            PatchGrid dab = flat.Clone();
            PatchBrush.Apply(dab, new BrushDab(BrushMode.Raise, 0.5, 0.5, 4.0 / m, 0.01)).ApplyTo(dab);
            PatchGrid other = PatchGrid.CreateFlat(m, m);
            foreach (GregoryPatch p in other.Patches)
                for (int k = 0; k < GregoryPatch.SlotCount; k++) p[k] = new Double3(p[k].x, p[k].y, 0.25);
            Console.WriteLine(FormattableString.Invariant($"# Undo per whole-grid step, bytes of control points recorded ({m} x {m} measured: {blocks} blocks of {PatchGridBlocks.BlockBytes} B; 1024 x 1024: {large} blocks)"));
            Console.WriteLine("step                                  blocks before -> now      1024 x 1024 before -> now (bytes)");
            // A change over the whole grid scales with the block count; a local one (the same patches) does not.
            void Row(string name, PatchGrid next, bool local = false)
            {
                int changed = PatchGridBlocks.ChangedBlocks(current, PatchGridBlocks.FromGrid(next)).Length;
                long scaled = local ? changed : (long)Math.Round((double)changed / blocks * large);
                Console.WriteLine(FormattableString.Invariant(
                    $"{name,-38}{blocks,6} -> {changed,-6}   {(long)large * PatchGridBlocks.BlockBytes,13:N0} -> {scaled * PatchGridBlocks.BlockBytes:N0}"));
            }
            Row("Enforce G1 on a grid already G1", g1);
            Row("Make flat grid on a flat grid", PatchGrid.CreateFlat(m, m));
            Row("Import: one brush-sized region differs", dab, local: true);
            Row("Fit to new heights (every patch)", other);
        }
    }
}
