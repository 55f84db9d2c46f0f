// The Horizon levels' tile factors from compute kernels (issue 38's route, measured in
// Tools~/bench/records.md, "Where the Horizon levels' vert + hull time goes"; the rig's prototype
// Tools~/rig/bench_lod_factors.hlsl): on lavapipe, in one frame, the kernels' factors for every
// draw patch against the ones the shipped hull stage returns for it (factor_readback+lod+noise), at
// 100 km and 1,000 km from the feet (the samples walking to the range origin). Equal bit for bit:
// the same culling, pieces, and seam rule (a fine seam edge takes g of the coarse edge's piece, which
// the kernel reads from the coarse tile's record instead of computing it again).
using System.Collections.Generic;
using System.IO;
using GregoryTerrain.Tests;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture, Parallelizable(ParallelScope.Self)]
    public class LodFactorKernelGpuTests
    {
        const int Tiles = 8;
        string _work, _spirv, _kernels;
        PatchGrid _grid;

        [OneTimeSetUp]
        public void CompileShaders()
        {
            _work = ReadbackRun.PrepareWork("rigtests-lod-factor-kernels");
            _spirv = ReadbackRun.CompileVariants(_work, "factor_readback+lod+noise");
            _kernels = Path.Combine(_work, "kernels");
            Directory.CreateDirectory(_kernels);
            string source = PackageRoot.Combine("Tools~", "rig", "bench_lod_factors.hlsl");
            foreach (string kernel in new[] { "lod_pieces", "lod_seams" })
                ReadbackRun.Exec("glslangValidator", new[] { "-D", "-V", "-S", "comp", "-e", kernel, "--hlsl-iomap",
                    "--shift-cbuffer-binding", "0", "--shift-texture-binding", "2", "--shift-UAV-binding", "5",
                    "-DGT_LOD", "-DGT_NOISE", "-DLOD_KERNELS", "-o", Path.Combine(_kernels, kernel + ".spv"), source }, null);
            _grid = HardCaseGrids.Fitted();
        }

        [TestCase(1e5)]
        [TestCase(1e6)]
        public void KernelFactorsEqualTheHullsBitForBit(double terrainMeters)
        {
            LodScene s = new LodScene { Tiles = Tiles, Factor = 0, Width = 1920, Height = 1080, TerrainMeters = terrainMeters }.Build(_grid);
            string dir = Path.Combine(_work, "t" + terrainMeters.ToString("0"));
            s.Write(dir);
            string hull = Path.Combine(dir, "hull.f32"), kernel = Path.Combine(dir, "kernel.f32");
            int p = s.Patches;
            var args = new List<string>(ReadbackRun.Stages(_spirv, "factor_readback+lod+noise"));
            args.AddRange(s.HarnessArgs(dir));
            args.AddRange(new[] { "--width", "192", "--height", "108", "--device", "llvmpipe", "--readback", hull, "--readback-floats", (8 * p).ToString(),
                "--storage", $"7:{32 * p}", "--storage", $"8:{32 * p}", "--storage", $"9:{64 * p}",
                "--compute", $"{Path.Combine(_kernels, "lod_pieces.spv")}:{p}", "--compute", $"{Path.Combine(_kernels, "lod_seams.spv")}:{(p + 63) / 64}",
                "--dump-storage", $"7:{kernel}" });
            HarnessRun.Harness(args.ToArray()).AssertSucceeded();
            float[] h = ReadbackRun.ReadFloats(hull), k = ReadbackRun.ReadFloats(kernel);
            var f = s.Tail;
            Float4 Range(int level) => new Float4(f[4 + 4 * level], f[5 + 4 * level], f[6 + 4 * level], f[7 + 4 * level]);
            int fineSeamEdges = 0;   // drawn fine seam edges: their factor is g of the coarse tile's edge
            for (int level = 0; level + 1 < s.LevelCount; level++)
            {
                LodTiles.FinerOffsetCells(Range(level + 1), Range(level), Tiles, out int a, out int b);
                for (int slot = 0; slot < Tiles * Tiles; slot++)
                {
                    int mask = LodTiles.FineSeamEdges(slot % Tiles, slot / Tiles, a, b, Tiles);
                    for (int e = 0; e < 4; e++)
                        if ((mask & (1 << e)) != 0 && h[8 * (level * Tiles * Tiles + slot) + e] != 0f) fineSeamEdges++;
                }
            }
            int drawn = 0, differ = 0;
            string first = null;
            for (int i = 0; i < p; i++)
            {
                bool same = true;
                for (int c = 0; c < 6; c++)
                    same &= h[8 * i + c] == k[8 * i + c];
                if (h[8 * i] != 0f) drawn++;
                if (!same)
                {
                    differ++;
                    first ??= $"patch {i}: hull ({string.Join(", ", h[8 * i], h[8 * i + 1], h[8 * i + 2], h[8 * i + 3], h[8 * i + 4], h[8 * i + 5])})"
                              + $" kernel ({string.Join(", ", k[8 * i], k[8 * i + 1], k[8 * i + 2], k[8 * i + 3], k[8 * i + 4], k[8 * i + 5])})";
                }
            }
            TestContext.Out.WriteLine($"lod factor kernels, {terrainMeters / 1000:0} km: {p} patches, {drawn} drawn, {fineSeamEdges} fine seam edges drawn, {differ} differ from the hull{(first == null ? "" : "; first " + first)}");
            Assert.That(drawn, Is.GreaterThan(Tiles * Tiles), "the view draws tiles of several levels");
            Assert.That(fineSeamEdges, Is.GreaterThan(4), "the seam rule is exercised");
            Assert.That(differ, Is.EqualTo(0), first);
        }
    }
}
