// What each of gt shaderlab's two compilers rejects, each run exactly as the check runs it (shaderlab.py's
// Rig.compile: glslang, its legalisation and spirv-val; Rig.dxc_compile: DXC -HV 2018 with DXC_OPTIONS),
// on minimal vertex programs that each hold one known fault. Neither rejects everything the other does,
// so the check keeps both for every case (Tools~/rig/README.md, "What each compiler checks").
using System.Diagnostics;
using System.IO;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    [TestFixture, Parallelizable(ParallelScope.Self)]
    public class ShaderCompilerReachTests
    {
        const string Entry = "float4 main(float2 uv : TEXCOORD0, uint id : SV_VertexID) : SV_Position";

        static readonly (string fault, string hlsl)[] Faults =
        {
            // FXC: a resource cannot come from a run-time choice. DXC with -fcgl -Vd neither legalises nor validates.
            ("resource-chosen-at-run-time", "Texture2D _A; Texture2D _B; SamplerState s_linear_clamp;\n"
                + "float4 Pick(bool c, float2 uv) { Texture2D t; if (c) t = _A; else t = _B; return t.SampleLevel(s_linear_clamp, uv, 0); }\n"
                + Entry + " { return Pick(id > 3, uv); }\n"),
            ("constant-index-out-of-range", "static const float k[4] = { 1, 2, 3, 4 };\n" + Entry + " { return k[5] * uv.xyxy; }\n"),
            ("input-without-semantic", "float4 main(float2 uv) : SV_Position { return uv.xyxy; }\n"),
            ("output-without-semantic", "struct V { float4 p : SV_Position; float2 uv; };\nV main(float2 uv : TEXCOORD0) { V v; v.p = uv.xyxy; v.uv = uv; return v; }\n"),
            ("conditional-on-structs", "struct P { float4 a; };\n" + Entry + " { P x, y; x.a = uv.xyxy; y.a = -uv.xyxy; P r = id > 3 ? x : y; return r.a; }\n"),
        };

        /// <summary>"glslang ok|fail" and "dxc ok|fail" for each fault, from shaderlab.py's own compile functions.</summary>
        static string Verdicts(string dir)
        {
            const string Probe = @"
import os, sys, tempfile
sys.path.insert(0, sys.argv[1])
import shaderlab
rig = shaderlab.Rig(sys.argv[2], sys.argv[3], tempfile.mkdtemp(dir=sys.argv[5]), 1, None, os.path.abspath(sys.argv[4]))
for name in sorted(os.listdir(sys.argv[5])):
    if not name.endswith('.hlsl'): continue
    path = os.path.join(sys.argv[5], name)
    case = shaderlab.Case('probe', name, path, 'vert', 'main', [], 50, ('probe', name))
    with open(path) as f: text = f.read()
    print(name[:-5], 'glslang', 'ok' if rig.compile(case, text)[0] else 'fail', 'dxc', 'ok' if rig.dxc_compile(case, [])[0] else 'fail')
";
            var psi = new ProcessStartInfo("python3") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
            foreach (string a in new[] { "-c", Probe, PackageRoot.Combine("Tools~", "rig"), PackageRoot.Path, ShaderLibraryTests.ShaderLib,
                                         PackageRoot.Combine("..", "shared", "dxc", "bin", "dxc"), dir })
                psi.ArgumentList.Add(a);
            using var p = Process.Start(psi);
            var err = p.StandardError.ReadToEndAsync();
            string output = p.StandardOutput.ReadToEnd();
            p.WaitForExit();
            Assert.That(p.ExitCode, Is.EqualTo(0), "the probe failed:\n" + output + err.Result);
            return output;
        }

        [Test]
        public void NeitherCompilerRejectsEverythingTheOtherDoes()
        {
            string dir = Path.Combine(Path.GetTempPath(), "gt-compiler-reach-" + System.Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(dir);
            try
            {
                foreach (var (fault, hlsl) in Faults) File.WriteAllText(Path.Combine(dir, fault + ".hlsl"), hlsl);
                string verdicts = Verdicts(dir);
                TestContext.Out.WriteLine(verdicts);
                Assert.Multiple(() =>
                {
                    Assert.That(verdicts, Does.Contain("resource-chosen-at-run-time glslang fail dxc ok"), "only glslang's legalisation and spirv-val see it");
                    Assert.That(verdicts, Does.Contain("constant-index-out-of-range glslang fail dxc fail"));
                    Assert.That(verdicts, Does.Contain("input-without-semantic glslang ok dxc fail"), "only DXC requires an input's semantic");
                    Assert.That(verdicts, Does.Contain("output-without-semantic glslang ok dxc fail"), "only DXC requires an output's semantic");
                    Assert.That(verdicts, Does.Contain("conditional-on-structs glslang ok dxc fail"), "only DXC holds HLSL 2018's ?: to scalars and vectors");
                });
            }
            finally { Directory.Delete(dir, true); }
        }
    }
}
