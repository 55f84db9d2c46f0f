using System;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// The rules of Tools~/rig/fxc_lint.py (FXC errors that glslang and DXC both accept), each on a
    /// minimal kernel or source: the faulty form is found, with its rule, line and cause; the fixed
    /// form (and code that only looks alike) gives no finding. `gt shaderlab` runs the same rules on
    /// every case of the package (ShaderLibraryTests.TheLintFindsNothing).
    /// </summary>
    [TestFixture, Parallelizable(ParallelScope.Self)]
    public class FxcLintTests
    {
        const string Kernel = @"
cbuffer Params : register(b0) { uint _Count; };
RWStructuredBuffer<float4> _Records : register(u0);
StructuredBuffer<float4> _Factors : register(t0);
groupshared float gtShared[64];
";

        static (int code, string output) Lint(string hlsl, params string[] args)
        {
            string file = Path.Combine(Path.GetTempPath(), "gt-fxc-lint-" + Guid.NewGuid().ToString("N") + ".hlsl");
            File.WriteAllText(file, hlsl);
            try
            {
                var psi = new ProcessStartInfo("python3") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
                psi.ArgumentList.Add(PackageRoot.Combine("Tools~", "rig", "fxc_lint.py"));
                psi.ArgumentList.Add(file);
                foreach (string a in args) psi.ArgumentList.Add(a);
                using var p = Process.Start(psi);
                var stderr = p.StandardError.ReadToEndAsync();
                string stdout = p.StandardOutput.ReadToEnd();
                p.WaitForExit();
                return (p.ExitCode, stdout + stderr.Result);
            }
            finally
            {
                File.Delete(file);
            }
        }

        static int LineOf(string hlsl, string marker) => hlsl.Split('\n').ToList().FindIndex(l => l.Contains(marker)) + 1;

        static void AssertFinding(string hlsl, string rule, string marker, string because, params string[] args)
        {
            var (code, output) = Lint(hlsl, args);
            TestContext.Out.WriteLine(output);
            Assert.That(output, Does.Match($@"lint {rule}: \S+:{LineOf(hlsl, marker)}: [^\n]*{Regex.Escape(because)}"), output);
            Assert.That(code, Is.EqualTo(1), output);
        }

        static void AssertClean(string hlsl, params string[] args)
        {
            var (code, output) = Lint(hlsl, args);
            Assert.That(output, Does.Contain("lint: 0 findings"), output);
            Assert.That(code, Is.EqualTo(0), output);
        }

        // --- barrier-in-varying-flow (FXC error X3663) ---------------------------------------------

        [Test]
        public void ABarrierAfterAReturnOnARwBufferReadIsFound()
        {
            string faulty = Kernel + @"
[numthreads(64, 1, 1)]
void K(uint3 group : SV_GroupID, uint lane : SV_GroupIndex)
{
    if (_Records[group.x].w != 0.0) return;
    gtShared[lane] = lane;
    GroupMemoryBarrierWithGroupSync();   // the barrier
    _Records[group.x * 64 + lane] = gtShared[63 - lane];
}";
            AssertFinding(faulty, "barrier-in-varying-flow", "// the barrier", "read of RW resource _Records", "--entry", "K");
            // Fixed: the read guards the work, every lane reaches the barrier.
            AssertClean(faulty.Replace("    if (_Records[group.x].w != 0.0) return;\n    gtShared[lane] = lane;",
                                       "    bool done = _Records[group.x].w != 0.0;\n    if (!done) gtShared[lane] = lane;"), "--entry", "K");
        }

        [Test]
        public void ABarrierUnderABranchOnTheThreadIdIsFoundAndOneOnGroupIdAndCbufferIsNot()
        {
            string faulty = Kernel + @"
[numthreads(64, 1, 1)]
void K(uint3 group : SV_GroupID, uint lane : SV_GroupIndex)
{
    if (group.x >= _Count) return;
    if (lane < 32)
    {
        gtShared[lane] = lane;
        GroupMemoryBarrierWithGroupSync();   // the barrier
    }
    _Records[lane] = gtShared[lane];
}";
            AssertFinding(faulty, "barrier-in-varying-flow", "// the barrier", "thread ID lane (SV_GroupIndex)", "--entry", "K");
            AssertClean(faulty.Replace("    if (lane < 32)\n    {\n        gtShared[lane] = lane;\n        GroupMemoryBarrierWithGroupSync();   // the barrier\n    }",
                                       "    if (lane < 32) gtShared[lane] = lane;\n    GroupMemoryBarrierWithGroupSync();"), "--entry", "K");
        }

        [Test]
        public void ABarrierInAFunctionCalledAfterADivergentBreakIsFound()
        {
            string faulty = Kernel + @"
void Sync() { AllMemoryBarrierWithGroupSync(); }   // the barrier
[numthreads(64, 1, 1)]
void K(uint lane : SV_GroupIndex)
{
    for (uint i = 0; i < 4; i++)
    {
        if (_Factors[lane * 4 + i].x > 0.0) break;
        gtShared[lane] += 1.0;
        Sync();
    }
    _Records[lane] = gtShared[lane];
}";
            AssertFinding(faulty, "barrier-in-varying-flow", "// the barrier", "the break at", "--entry", "K");
            AssertClean(faulty.Replace("        if (_Factors[lane * 4 + i].x > 0.0) break;\n        gtShared[lane] += 1.0;",
                                       "        if (_Factors[lane * 4 + i].x <= 0.0) gtShared[lane] += 1.0;"), "--entry", "K");
        }

        // --- uav-loop-condition ([allow_uav_condition]) ---------------------------------------------

        [Test]
        public void ALoopEndingOnARwBufferReadNeedsAllowUavCondition()
        {
            string faulty = Kernel + @"
[numthreads(64, 1, 1)]
void K(uint3 group : SV_GroupID, uint lane : SV_GroupIndex)
{
    float4 f = _Records[group.x];
    uint count = (uint)(f.x + f.y);
    for (uint k = lane; k < count; k += 64)   // the loop
        _Records[1024 + k] = f;
}";
            AssertFinding(faulty, "uav-loop-condition", "// the loop", "read of RW resource _Records", "--entry", "K");
            // Fixed either way: read through the read-only view, or say so with the attribute.
            AssertClean(faulty.Replace("float4 f = _Records[group.x];", "float4 f = _Factors[group.x];"), "--entry", "K");
            AssertClean(faulty.Replace("    for (uint k = lane;", "    [allow_uav_condition] for (uint k = lane;"), "--entry", "K");
        }

        [Test]
        public void AnAllowUavConditionLoopMayHoldNoBarrier()
        {
            string faulty = Kernel + @"
[numthreads(64, 1, 1)]
void K(uint lane : SV_GroupIndex)
{
    [allow_uav_condition] for (uint k = 0; k < (uint)_Records[0].x; k++)   // the loop
    {
        gtShared[lane] += k;
        GroupMemoryBarrier();
    }
    _Records[lane] = gtShared[lane];
}";
            AssertFinding(faulty, "uav-loop-condition", "// the loop", "contains a barrier", "--entry", "K");
            AssertClean(faulty.Replace("        GroupMemoryBarrier();\n", ""), "--entry", "K");
        }

        // --- reserved-name ---------------------------------------------------------------------------

        [Test]
        public void AKeywordOrAUnityDefinedTypeAsANameIsFound()
        {
            string shaderlib = ShaderLibraryTests.ShaderLib;
            string faulty = @"
int2 Tile(uint edge, out int half)   // the parameter
{
    half = (int)edge % 2;
    return int2(half, 0);
}";
            AssertFinding(faulty, "reserved-name", "// the parameter", "an HLSL keyword", "--source", "--shaderlib", shaderlib);
            AssertFinding(faulty, "reserved-name", "// the parameter", "Unity's headers #define it as float (HLSLSupport.cginc)", "--source", "--shaderlib", shaderlib);
            AssertFinding("float Scale(float x)\n{\n    float real = x * 2.0;   // the local\n    return real;\n}\n",
                          "reserved-name", "// the local", "Unity's headers #define it as", "--source", "--shaderlib", shaderlib);
            AssertFinding("struct Hit { float3 point; };   // the member\n", "reserved-name", "// the member", "an HLSL keyword", "--source", "--shaderlib", shaderlib);
            // Fixed names, and the same words where they are types or casts, give nothing.
            AssertClean(faulty.Replace("half", "upperHalf"), "--source", "--shaderlib", shaderlib);
            AssertClean("half Twice(half x) { return (half)2.0 * half(x); }\nStructuredBuffer<float4> _Points;\n",
                        "--source", "--shaderlib", shaderlib);
        }

        // --- groupshared-limit (cs_5_0: 32 KB) -------------------------------------------------------

        [Test]
        public void MoreThan32KBOfGroupsharedIsFound()
        {
            string faulty = @"
RWStructuredBuffer<float4> _Out : register(u0);
groupshared float4 gtRows[2049];
[numthreads(64, 1, 1)]
void K(uint lane : SV_GroupIndex)   // the kernel
{
    gtRows[lane] = lane;
    GroupMemoryBarrierWithGroupSync();
    _Out[lane] = gtRows[63 - lane];
}";
            AssertFinding(faulty, "groupshared-limit", "// the kernel", "32784 bytes", "--entry", "K");
            AssertClean(faulty.Replace("[2049]", "[2048]"), "--entry", "K");
        }
    }
}
