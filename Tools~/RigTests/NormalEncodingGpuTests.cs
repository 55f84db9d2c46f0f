using System;
using System.IO;
using System.Linq;
using GregoryTerrain.Tests;
using NUnit.Framework;
using static GregoryTerrain.Rig.Tests.ComputeRunner;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// Shaders/Library/NormalEncoding.hlsl (the normal in the varyings) on lavapipe against Core's mirror
    /// NormalEncoding, through the probe kernel NormalEncodingProbe.hlsl run by gt-compute.
    /// </summary>
    [TestFixture, Parallelizable(ParallelScope.Self)]
    public class NormalEncodingGpuTests
    {
        [Test]
        public void LavapipeEncodesAndDecodesAsCore()
        {
            string dir = Path.Combine(Path.GetTempPath(), "gt-normal-encoding-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(dir);
            try
            {
                string spv = Path.Combine(dir, "probe.spv");
                Run("glslangValidator", "-D", "-V", "-S", "comp", "-e", "NormalEncodingProbe", "-o", spv,
                    PackageRoot.Combine("Tools~", "RigTests", "NormalEncodingProbe.hlsl"));
                Run("spirv-val", spv);

                // The sphere, plus straight up, straight down and the horizon.
                var normals = NormalEncodingTests.SphereNormals(64 * 156)
                    .Select(n => new Float3((float)n.x, (float)n.y, (float)n.z))
                    .Concat(new[] { new Float3(0f, 1f, 0f), new Float3(0f, -1f, 0f), new Float3(1f, 0f, 0f), new Float3(0f, 0f, -1f) })
                    .ToList();
                while (normals.Count % 64 != 0) normals.Add(new Float3(0f, 1f, 0f));
                var input = new float[4 * normals.Count];
                for (int i = 0; i < normals.Count; i++)
                {
                    input[4 * i] = normals[i].x; input[4 * i + 1] = normals[i].y; input[4 * i + 2] = normals[i].z;
                }
                string inFile = Path.Combine(dir, "normals.f32"), outFile = Path.Combine(dir, "encoded.f32");
                ReadbackRun.WriteFloats(inFile, input);
                string o = Run(Runner(), "--spv", spv, "--entry", "NormalEncodingProbe", "--device", "llvmpipe",
                    "--groups", (normals.Count / 64).ToString(), "--buffer", "0=" + inFile,
                    "--zeros", $"1={32 * normals.Count}", "--out", "1=" + outFile);
                Assert.That(o, Does.Contain("device llvmpipe"));
                float[] gpu = ReadbackRun.ReadFloats(outFile);
                Assert.That(gpu.Length, Is.EqualTo(8 * normals.Count));

                double worstCode = 0, worstNormal = 0;
                for (int i = 0; i < normals.Count; i++)
                {
                    Float2 e = NormalEncoding.LambertEncodeNormal(normals[i]);
                    Float3 d = NormalEncoding.LambertDecodeNormal(e);
                    // Relative to the code's size: rsqrt may differ by a few ulp between the two.
                    worstCode = Math.Max(worstCode, Math.Max(Math.Abs(gpu[8 * i] - e.x), Math.Abs(gpu[8 * i + 1] - e.y)) / Math.Max(1.0, Math.Sqrt(e.x * e.x + e.y * e.y)));
                    worstNormal = Math.Max(worstNormal, Math.Max(Math.Abs(gpu[8 * i + 4] - d.x), Math.Max(Math.Abs(gpu[8 * i + 5] - d.y), Math.Abs(gpu[8 * i + 6] - d.z))));
                }
                TestContext.Out.WriteLine("{0} normals: code differs by {1:G3} (relative), decoded normal by {2:G3}", normals.Count, worstCode, worstNormal);
                Assert.That(gpu[8 * (64 * 156)], Is.EqualTo(0f), "straight up encodes to the centre");
                Assert.That(gpu[8 * (64 * 156) + 5], Is.EqualTo(1f), "and decodes to straight up");
                Assert.That(worstCode, Is.LessThan(1e-6));
                Assert.That(worstNormal, Is.LessThan(2e-6));
            }
            finally { Directory.Delete(dir, true); }
        }
    }
}
