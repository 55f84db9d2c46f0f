using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Runtime.InteropServices;
using System.Text.Json;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// The C# to GPU contract (internals.md, "One contract to the GPU"): Runtime/ShaderIds.cs names
    /// every property, buffer, keyword and kernel the shaders declare and nothing else, no other
    /// Unity-side file spells a shader name, and Core's blittable <see cref="TerrainParams"/> has the
    /// layout the shader compiler gives the HLSL cbuffer (read back from SPIR-V with spirv-cross).
    /// </summary>
    [TestFixture]
    public class ShaderContractTests
    {
        /// <summary>
        /// Names the HLSL declares that the package's C# never sets, each with its reason. Anything
        /// else declared and not in ShaderIds fails.
        /// </summary>
        static readonly Dictionary<string, string> NotSetByThePackage = new Dictionary<string, string>
        {
            ["_LightDirection"] = "URP sets it for its shadow caster pass",
            ["_LightPosition"] = "URP sets it for its shadow caster pass",
            ["_ObjectId"] = "the editor's selection outline (SceneSelectionPass) sets it",
            ["_PassValue"] = "the editor's selection outline (SceneSelectionPass) sets it",
            ["_SelectionID"] = "the editor's scene picking (LightMode Picking) sets it",
            ["_Readback"] = "rig only (GT_READBACK, GT_FACTOR_READBACK): the harness binds it by register",
        };

        /// <summary>Adapters only the rig includes: their constants come from the rig's own upload.</summary>
        static readonly string[] RigOnlyFiles = { "Shaders/Pipelines/StandaloneAdapter.hlsl", "Shaders/Rig/TerrainRig.hlsl" };

        static string ShaderIdsSource() => File.ReadAllText(PackageRoot.Combine("Runtime", "ShaderIds.cs"));

        [Test]
        public void ShaderIdsNamesEveryPropertyTheShadersDeclareAndNoOther()
        {
            var named = NamesInShaderIds(ShaderIdsSource());
            var declared = DeclaredProperties(ShaderFiles());
            Assert.That(declared.Count, Is.GreaterThan(20), "HLSL declarations found: " + string.Join(", ", declared));
            CompareProperties(named.properties, declared);
        }

        [Test]
        public void ShaderIdsNamesEveryKeywordAndKernelTheShadersDeclareAndNoOther()
        {
            var named = NamesInShaderIds(ShaderIdsSource());
            var files = ShaderFiles().Concat(new[] { PackageRoot.Combine("Shaders", "GregoryTerrain.shader") }).ToList();
            var keywords = new SortedSet<string>(StringComparer.Ordinal);
            var kernels = new SortedSet<string>(StringComparer.Ordinal);
            foreach (string f in files)
                foreach (string line in File.ReadAllLines(f).Select(StripComment))
                {
                    Match m = Regex.Match(line, @"^\s*#pragma\s+(multi_compile|shader_feature)\w*\s+(.*)$");
                    if (m.Success)
                        foreach (string k in m.Groups[2].Value.Split(' ', StringSplitOptions.RemoveEmptyEntries))
                            if (k.StartsWith("GT_")) keywords.Add(k);
                    m = Regex.Match(line, @"^\s*#pragma\s+kernel\s+(\w+)");
                    if (m.Success) kernels.Add(m.Groups[1].Value);
                }
            Assert.That(keywords.Count, Is.GreaterThanOrEqualTo(7), "GT_ keywords found in the pragmas");
            Assert.That(kernels.Count, Is.GreaterThanOrEqualTo(5), "kernels found");
            Assert.That(named.keywords, Is.EquivalentTo(keywords), "keywords: Core's ShaderKeywords vs the shaders' #pragma multi_compile/shader_feature (the compute files' too)");
            Assert.That(named.kernels, Is.EquivalentTo(kernels), "kernels: ShaderIds vs the compute files' #pragma kernel");
        }

        /// <summary>The material's Properties block: TerrainParams defaults, and toggles whose keyword ShaderIds names.</summary>
        [Test]
        public void TheMaterialPropertiesAreTerrainParamsOrKeywordToggles()
        {
            string shader = File.ReadAllText(PackageRoot.Combine("Shaders", "GregoryTerrain.shader"));
            int start = shader.IndexOf("Properties", StringComparison.Ordinal);
            int open = shader.IndexOf('{', start), close = shader.IndexOf('}', open);
            var named = NamesInShaderIds(ShaderIdsSource());
            var bad = new List<string>();
            int seen = 0;
            foreach (string line in shader.Substring(open + 1, close - open - 1).Split('\n').Select(StripComment))
            {
                Match m = Regex.Match(line, @"^\s*((?:\[[^\]]*\]\s*)*)(\w+)\s*\(");
                if (!m.Success) continue;
                seen++;
                string attributes = m.Groups[1].Value, property = m.Groups[2].Value;
                Match toggle = Regex.Match(attributes, @"\[Toggle\((\w+)\)\]");
                if (toggle.Success)
                {
                    if (!named.keywords.Contains(toggle.Groups[1].Value)) bad.Add($"{property}: toggle keyword {toggle.Groups[1].Value} not in ShaderIds");
                }
                else if (attributes.Contains("KeywordEnum"))
                {
                    if (!named.keywords.Any(k => k.StartsWith(property + "_"))) bad.Add($"{property}: no {property}_* keyword in ShaderIds");
                }
                else if (!TerrainParams.PropertyNames.Contains(property))
                    bad.Add($"{property}: not a TerrainParams constant");
            }
            Assert.That(seen, Is.GreaterThanOrEqualTo(10), "Properties found");
            Assert.That(bad, Is.Empty);
        }

        /// <summary>
        /// ShaderIds is the only Unity-side C# that spells a shader name: no PropertyToID, no GT_
        /// keyword and no kernel name in a string anywhere else in Runtime/ or Editor/.
        /// </summary>
        [Test]
        public void NoOtherRuntimeOrEditorFileSpellsAShaderName()
        {
            var named = NamesInShaderIds(ShaderIdsSource());
            var all = new HashSet<string>(named.properties.Concat(named.keywords).Concat(named.kernels), StringComparer.Ordinal);
            string ids = Path.GetFullPath(PackageRoot.Combine("Runtime", "ShaderIds.cs"));
            string core = Path.GetFullPath(PackageRoot.Combine("Runtime", "Core")) + Path.DirectorySeparatorChar;
            var bad = new List<string>();
            foreach (string dir in new[] { "Runtime", "Editor" })
                foreach (string f in Directory.GetFiles(PackageRoot.Combine(dir), "*.cs", SearchOption.AllDirectories))
                {
                    string full = Path.GetFullPath(f);
                    if (full == ids || full.StartsWith(core)) continue;   // Core names TerrainParams' members: the mirror
                    string[] lines = File.ReadAllLines(f);
                    for (int i = 0; i < lines.Length; i++)
                    {
                        string line = StripComment(lines[i]);
                        if (line.Contains("PropertyToID(")) bad.Add($"{Rel(f)}:{i + 1}: PropertyToID");
                        foreach (Match m in Regex.Matches(line, "\"(\\w+)\""))
                            if (all.Contains(m.Groups[1].Value) || m.Groups[1].Value.StartsWith("GT_"))
                                bad.Add($"{Rel(f)}:{i + 1}: \"{m.Groups[1].Value}\"");
                    }
                }
            Assert.That(bad, Is.Empty, "use ShaderIds");
        }

        // ---- TerrainParams: the C# struct against the compiled cbuffer ----------------------------

        [TestCase(false)]
        [TestCase(true)]
        public void TerrainParamsHasTheLayoutOfTheCompiledCbuffer(bool snow)
        {
            var members = CompiledTerrainParams(snow, out int blockSize);
            CompareLayout(members);
            if (snow)
            {
                // The snow variant's one extra constant sits right after the struct's 160 bytes.
                Assert.That(members.Last(), Is.EqualTo(("_SnowMapSize", TerrainParams.Bytes)), "GT_SNOW: _SnowMapSize last");
                Assert.That(blockSize, Is.EqualTo(TerrainParams.Bytes + 16));
            }
            else Assert.That(blockSize, Is.EqualTo(TerrainParams.Bytes));
        }

        /// <summary>The struct is blittable and its fields are float4 named after the shader constants.</summary>
        [Test]
        public void TerrainParamsIsBlittableFloat4sNamedAfterTheConstants()
        {
            Assert.That(Marshal.SizeOf<TerrainParams>(), Is.EqualTo(TerrainParams.Bytes));
            var fields = InstanceFields();
            Assert.That(fields.Select(f => f.FieldType), Is.All.EqualTo(typeof(Float4)));
            Assert.That(fields.Select(ShaderName),
                Is.EqualTo(TerrainParams.PropertyNames), "field k is PropertyNames[k] (rangeOrigin is _RangeOrigin)");
            // Pack is the struct's bytes, and the indexer reads the same fields.
            var p = new TerrainParams { range = new Float4(1, 2, 3, 4), tess = new Float4(5, 6, 7, 8), tileLattice = new Float4(9, 10, 11, 12) };
            float[] f = p.Pack();
            for (int k = 0; k < TerrainParams.Float4Count; k++)
                Assert.That(new[] { f[4 * k], f[4 * k + 1], f[4 * k + 2], f[4 * k + 3] },
                    Is.EqualTo(new[] { p[k].x, p[k].y, p[k].z, p[k].w }), TerrainParams.PropertyNames[k]);
        }

        /// <summary>
        /// The comparison the layout test makes, on a cbuffer with two members swapped: it fails,
        /// naming the field (a broken mirror cannot pass).
        /// </summary>
        [Test]
        public void ASwappedCbufferMemberFailsTheLayoutComparison()
        {
            var members = CompiledTerrainParams(false, out _);
            var swapped = members.ToList();
            (swapped[2], swapped[3]) = ((swapped[3].name, swapped[2].offset), (swapped[2].name, swapped[3].offset));
            var e = Assert.Throws<AssertionException>(() => CompareLayout(swapped));
            Assert.That(e.Message, Does.Contain("TerrainParams.gridSize").And.Contain("_GridSize"));
        }

        /// <summary>The property comparison on a broken name: a misspelt declaration fails both ways.</summary>
        [Test]
        public void AMisspeltNameFailsThePropertyComparison()
        {
            var named = NamesInShaderIds(ShaderIdsSource().Replace("\"_SnowMapSize\"", "\"_SnowMapSiz\""));
            var declared = DeclaredProperties(ShaderFiles());
            var e = Assert.Throws<AssertionException>(() => CompareProperties(named.properties, declared));
            Assert.That(e.Message, Does.Contain("_SnowMapSiz").And.Contain("_SnowMapSize"));
        }

        /// <summary>
        /// Each C# field (as its shader name) at the byte offset the compiler gave that cbuffer
        /// member, and <see cref="TerrainParams.PropertyNames"/> in the cbuffer's member order.
        /// </summary>
        static void CompareLayout(IReadOnlyList<(string name, int offset)> compiled)
        {
            var fields = InstanceFields();
            foreach (FieldInfo f in fields)
            {
                int offset = (int)Marshal.OffsetOf<TerrainParams>(f.Name);
                string shaderName = ShaderName(f);
                var member = compiled.Where(c => c.name == shaderName).ToList();
                Assert.That(member.Count, Is.EqualTo(1), $"TerrainParams.{f.Name}: the cbuffer has no member {shaderName}");
                Assert.That(member[0].offset, Is.EqualTo(offset),
                    $"TerrainParams.{f.Name} is at byte {offset} in C#, {shaderName} at byte {member[0].offset} in the cbuffer");
            }
            Assert.That(compiled.Take(fields.Count).Select(c => c.name), Is.EqualTo(TerrainParams.PropertyNames),
                "TerrainParams.PropertyNames vs the cbuffer's member order");
        }

        /// <summary>The shader constant a field declares: rangeOrigin is _RangeOrigin (the generator's rule).</summary>
        static string ShaderName(FieldInfo f) => ContractGenerator.ShaderName(f);

        static List<FieldInfo> InstanceFields() =>
            typeof(TerrainParams).GetFields(BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic)
                .OrderBy(f => (int)Marshal.OffsetOf<TerrainParams>(f.Name)).ToList();

        /// <summary>
        /// Compiles SnowField.compute (a product kernel that includes TerrainInputs.hlsl) with glslang's
        /// HLSL front end and reads the TerrainParams block's members and offsets back from the SPIR-V.
        /// </summary>
        static List<(string name, int offset)> CompiledTerrainParams(bool snow, out int blockSize) =>
            CompiledCbuffer(PackageRoot.Combine("Shaders", "Snow", "SnowField.compute"), "SnowFieldKernel", "TerrainParams", snow ? "-DGT_SNOW" : null, out blockSize);

        /// <summary>A compute file's cbuffer <paramref name="block"/> as glslang lays it out: members and byte offsets, from the SPIR-V.</summary>
        static List<(string name, int offset)> CompiledCbuffer(string file, string kernel, string block, string define, out int blockSize)
        {
            string dir = Path.Combine(Path.GetTempPath(), "gt-contract-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(dir);
            try
            {
                string spv = Path.Combine(dir, "kernel.spv");
                var args = new List<string> { "-D", "-V", "-S", "comp", "-e", kernel, "-o", spv };
                if (define != null) args.Add(define);
                args.Add(file);
                ComputeRunner.Run("glslangValidator", args.ToArray());
                using var doc = JsonDocument.Parse(ComputeRunner.Run("spirv-cross", spv, "--reflect"));
                JsonElement ubo = doc.RootElement.GetProperty("ubos").EnumerateArray()
                    .Single(u => u.GetProperty("name").GetString() == block);
                blockSize = ubo.GetProperty("block_size").GetInt32();
                JsonElement type = doc.RootElement.GetProperty("types").GetProperty(ubo.GetProperty("type").GetString());
                return type.GetProperty("members").EnumerateArray()
                    .Select(m => (m.GetProperty("name").GetString(), m.GetProperty("offset").GetInt32())).ToList();
            }
            finally { Directory.Delete(dir, true); }
        }

        /// <summary>
        /// Core's <see cref="SnowParams"/> against SnowSimulation.compute's cbuffer as compiled: each
        /// field (as its shader name) at its C# offset, in order, 80 bytes in all.
        /// </summary>
        [Test]
        public void SnowParamsHasTheLayoutOfTheCompiledCbuffer()
        {
            var compiled = CompiledCbuffer(PackageRoot.Combine("Shaders", "Snow", "SnowSimulation.compute"), "SnowAccumulateKernel", "SnowParams", null, out int blockSize);
            var expected = typeof(SnowParams).GetFields(BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic)
                .Select(f => (ShaderName(f), (int)Marshal.OffsetOf<SnowParams>(f.Name))).OrderBy(m => m.Item2).ToList();
            Assert.That(compiled, Is.EqualTo(expected), "SnowParams: (shader name, byte offset) in C# vs the compiled cbuffer");
            Assert.That(expected.Select(m => m.Item1), Is.EqualTo(SnowParams.PropertyNames));
            Assert.That(blockSize, Is.EqualTo(Marshal.SizeOf<SnowParams>()).And.EqualTo(80));
        }

        /// <summary>
        /// Core's blittable <see cref="GregoryPatchRecord"/> against the HLSL struct the compiler lays
        /// out for <c>StructuredBuffer&lt;GregoryPatchRecord&gt; _ControlPoints</c>: the buffer's stride,
        /// and field <c>point</c>k at the byte of <c>points[k]</c>.
        /// </summary>
        [Test]
        public void PatchRecordMatchesTheCompiledStruct()
        {
            CompiledRecord compiled = CompiledPatchRecord(PackageRoot.Combine("Shaders"));
            Assert.That(compiled.recordStride, Is.EqualTo(320), "the compiled _ControlPoints stride");
            ComparePatchRecord(compiled);
            Assert.That(GpuLayout.PatchRecordStride, Is.EqualTo(compiled.recordStride), "GpuLayout.PatchRecordStride (the renderer's buffer stride)");
        }

        /// <summary>
        /// Core's cache records against the structs the compiler lays out for the kernels' buffers
        /// (TerrainCache.compute): the stride the renderer gives each GraphicsBuffer, and every field
        /// (an HlslArray field k at its array's element k) at its compiled byte.
        /// </summary>
        [TestCase("CacheTileFactors", null, "_TileFactorsRW", typeof(TileFactorRecord), TileFactorRecord.Stride)]
        [TestCase("CacheTileFactors", null, "_TileCellsRW", typeof(TileCellRecord), TileCellRecord.Stride)]
        [TestCase("LodFactorSeams", "GT_LOD", "_LodFactorsRW", typeof(LodFactorRecord), LodFactorRecord.Stride)]
        public void CacheRecordsMatchTheCompiledStructs(string kernel, string keyword, string buffer, Type record, int stride)
        {
            string dir = Path.Combine(Path.GetTempPath(), "gt-contract-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(dir);
            try
            {
                string spv = Path.Combine(dir, "kernel.spv");
                var args = new List<string> { "-D", "-V", "-S", "comp", "-e", kernel, "-o", spv };
                if (keyword != null) args.Add("-D" + keyword);
                args.Add(PackageRoot.Combine("Shaders", "Cache", "TerrainCache.compute"));
                ComputeRunner.Run("glslangValidator", args.ToArray());
                using var doc = JsonDocument.Parse(ComputeRunner.Run("spirv-cross", spv, "--reflect"));
                JsonElement types = doc.RootElement.GetProperty("types");
                JsonElement ssbo = doc.RootElement.GetProperty("ssbos").EnumerateArray().Single(b => b.GetProperty("name").GetString() == buffer);
                JsonElement data = types.GetProperty(ssbo.GetProperty("type").GetString()).GetProperty("members").EnumerateArray().Single();
                JsonElement compiled = types.GetProperty(data.GetProperty("type").GetString());
                Assert.That(compiled.GetProperty("name").GetString(), Is.EqualTo(record.Name), buffer + "'s element type");
                Assert.That(data.GetProperty("array_stride").GetInt32(), Is.EqualTo(stride).And.EqualTo(Marshal.SizeOf(record)),
                            $"{buffer}'s compiled stride vs {record.Name}.Stride and its C# size");
                var offsets = new List<(string, int)>();
                foreach (JsonElement m in compiled.GetProperty("members").EnumerateArray())
                {
                    int offset = m.GetProperty("offset").GetInt32();
                    if (!m.TryGetProperty("array", out JsonElement array)) { offsets.Add((m.GetProperty("name").GetString(), offset)); continue; }
                    for (int k = 0; k < array.EnumerateArray().Single().GetInt32(); k++)
                        offsets.Add((m.GetProperty("name").GetString() + "[" + k + "]", offset + k * m.GetProperty("array_stride").GetInt32()));
                }
                var fields = record.GetFields(BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic)
                    .Select(f => (int)Marshal.OffsetOf(record, f.Name)).OrderBy(o => o).ToList();
                Assert.That(offsets.Select(o => o.Item2), Is.EqualTo(fields),
                            $"{record.Name}: C# field offsets vs the compiled members ({string.Join(", ", offsets.Select(o => o.Item1 + " @" + o.Item2))})");
            }
            finally { Directory.Delete(dir, true); }
        }

        /// <summary>The record comparison on a broken HLSL struct (19 points): it fails naming both sides.</summary>
        [Test]
        public void AShortHlslRecordFailsTheRecordComparison()
        {
            string copy = Path.Combine(Path.GetTempPath(), "gt-contract-" + Guid.NewGuid().ToString("N"));
            try
            {
                CopyTree(PackageRoot.Combine("Shaders"), copy);
                string record = Path.Combine(copy, "Terrain", "GregoryPatchRecord.cs.hlsl");   // generated from Core's struct
                string text = File.ReadAllText(record);
                Assert.That(text, Does.Contain("float4 points[20];"));
                File.WriteAllText(record, text.Replace("float4 points[20];", "float4 points[19];"));
                CompiledRecord compiled = CompiledPatchRecord(copy);
                Assert.That(compiled.recordStride, Is.EqualTo(304));
                var e = Assert.Throws<AssertionException>(() => ComparePatchRecord(compiled));
                Assert.That(e.Message, Does.Contain("304").And.Contain("320"));
            }
            finally { if (Directory.Exists(copy)) Directory.Delete(copy, true); }
        }

        struct CompiledRecord
        {
            public string structName, member;
            public int recordStride, memberOffset, length, elementStride;
        }

        static void ComparePatchRecord(CompiledRecord compiled)
        {
            int size = Marshal.SizeOf<GregoryPatchRecord>();
            Assert.That(compiled.structName, Is.EqualTo(nameof(GregoryPatchRecord)), "_ControlPoints' element type");
            Assert.That(compiled.recordStride, Is.EqualTo(size),
                $"GregoryPatchRecord is {size} bytes in C#, the compiled _ControlPoints stride is {compiled.recordStride}");
            Assert.That(GregoryPatchRecord.Stride, Is.EqualTo(size), "GregoryPatchRecord.Stride vs Marshal.SizeOf");
            var fields = typeof(GregoryPatchRecord).GetFields(BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic)
                .OrderBy(f => (int)Marshal.OffsetOf<GregoryPatchRecord>(f.Name)).ToList();
            Assert.That(fields.Count, Is.EqualTo(compiled.length),
                $"GregoryPatchRecord has {fields.Count} fields, the HLSL {compiled.member}[{compiled.length}]");
            Assert.That(GregoryPatchRecord.PointCount, Is.EqualTo(compiled.length), "GregoryPatchRecord.PointCount");
            for (int k = 0; k < fields.Count; k++)
            {
                FieldInfo f = fields[k];
                int offset = (int)Marshal.OffsetOf<GregoryPatchRecord>(f.Name);
                int expected = compiled.memberOffset + k * compiled.elementStride;
                Assert.That(f.Name, Is.EqualTo("point" + k), "GregoryPatchRecord's fields in slot order");
                Assert.That(f.FieldType, Is.EqualTo(typeof(Float4)), $"GregoryPatchRecord.{f.Name}: the HLSL element is a float4");
                Assert.That(offset, Is.EqualTo(expected),
                    $"GregoryPatchRecord.{f.Name} is at byte {offset} in C#, {compiled.member}[{k}] at byte {expected} in the compiled struct");
            }
        }

        /// <summary>
        /// Compiles SnowField.compute of a Shaders tree (it reads _ControlPoints through PatchGrid.hlsl)
        /// and reads the _ControlPoints buffer's element struct back from the SPIR-V: its stride, its one
        /// member's name, offset, array length and array stride.
        /// </summary>
        static CompiledRecord CompiledPatchRecord(string shaders)
        {
            string dir = Path.Combine(Path.GetTempPath(), "gt-contract-" + Guid.NewGuid().ToString("N"));
            Directory.CreateDirectory(dir);
            try
            {
                string spv = Path.Combine(dir, "field.spv");
                ComputeRunner.Run("glslangValidator", "-D", "-V", "-S", "comp", "-e", "SnowFieldKernel", "-o", spv,
                    Path.Combine(shaders, "Snow", "SnowField.compute"));
                using var doc = JsonDocument.Parse(ComputeRunner.Run("spirv-cross", spv, "--reflect"));
                JsonElement types = doc.RootElement.GetProperty("types");
                JsonElement ssbo = doc.RootElement.GetProperty("ssbos").EnumerateArray()
                    .Single(b => b.GetProperty("name").GetString() == "_ControlPoints");
                JsonElement data = types.GetProperty(ssbo.GetProperty("type").GetString()).GetProperty("members").EnumerateArray().Single();
                JsonElement record = types.GetProperty(data.GetProperty("type").GetString());
                JsonElement member = record.GetProperty("members").EnumerateArray().Single();
                return new CompiledRecord
                {
                    structName = record.GetProperty("name").GetString(),
                    recordStride = data.GetProperty("array_stride").GetInt32(),
                    member = member.GetProperty("name").GetString(),
                    memberOffset = member.GetProperty("offset").GetInt32(),
                    length = member.GetProperty("array").EnumerateArray().Single().GetInt32(),
                    elementStride = member.GetProperty("array_stride").GetInt32(),
                };
            }
            finally { Directory.Delete(dir, true); }
        }

        static void CopyTree(string from, string to)
        {
            foreach (string d in Directory.GetDirectories(from, "*", SearchOption.AllDirectories))
                Directory.CreateDirectory(Path.Combine(to, Path.GetRelativePath(from, d)));
            Directory.CreateDirectory(to);
            foreach (string f in Directory.GetFiles(from, "*", SearchOption.AllDirectories))
                File.Copy(f, Path.Combine(to, Path.GetRelativePath(from, f)));
        }

        // ---- parsing -------------------------------------------------------------------------------

        static void CompareProperties(ISet<string> named, ISet<string> declared)
        {
            var missing = declared.Where(n => !named.Contains(n) && !NotSetByThePackage.ContainsKey(n)).ToList();
            var extra = named.Where(n => !declared.Contains(n)).ToList();
            var exemptButNamed = named.Where(NotSetByThePackage.ContainsKey).ToList();
            Assert.That(missing.Concat(extra).Concat(exemptButNamed), Is.Empty,
                $"declared in HLSL, not in ShaderIds: [{string.Join(", ", missing)}]; in ShaderIds, declared nowhere: [{string.Join(", ", extra)}]; " +
                $"named although the package never sets them: [{string.Join(", ", exemptButNamed)}]");
        }

        /// <summary>The identifier-like string literals of ShaderIds.cs by kind, plus the names Core's contracts generate (TerrainParams, SnowParams).</summary>
        static (SortedSet<string> properties, SortedSet<string> keywords, SortedSet<string> kernels) NamesInShaderIds(string source)
        {
            var properties = new SortedSet<string>(TerrainParams.PropertyNames.Concat(SnowParams.PropertyNames), StringComparer.Ordinal);
            // The keywords are Core's one declaration (ShaderKeywords), which the .shader's pragmas are generated from.
            var keywords = new SortedSet<string>(ShaderKeywords.Sets.SelectMany(s => s.Keywords.Select(k => k.name)), StringComparer.Ordinal);
            var kernels = new SortedSet<string>(StringComparer.Ordinal);
            foreach (string line in source.Split('\n').Select(StripComment))
                foreach (Match m in Regex.Matches(line, "(?<![$\\w])\"([A-Za-z_]\\w*)\""))
                {
                    string s = m.Groups[1].Value;
                    (s.StartsWith("GT_") ? keywords : s.StartsWith("_") ? properties : kernels).Add(s);
                }
            return (properties, keywords, kernels);
        }

        /// <summary>Shaders/ HLSL and compute files, without the rig-only ones.</summary>
        static List<string> ShaderFiles() =>
            Directory.GetFiles(PackageRoot.Combine("Shaders"), "*.*", SearchOption.AllDirectories)
                .Where(f => f.EndsWith(".hlsl") || f.EndsWith(".compute"))
                .Where(f => !RigOnlyFiles.Any(r => Rel(f) == r)).OrderBy(f => f, StringComparer.Ordinal).ToList();

        /// <summary>
        /// Resources and constants: every (RW)StructuredBuffer, every member of a cbuffer block
        /// (cbuffer or GT_CBUFFER_START) and every global at column 0 whose name starts with '_'.
        /// </summary>
        internal static SortedSet<string> DeclaredProperties(IEnumerable<string> files)
        {
            var names = new SortedSet<string>(StringComparer.Ordinal);
            foreach (string f in files)
            {
                bool inBlock = false;
                foreach (string raw in File.ReadAllLines(f))
                {
                    string line = StripComment(raw);
                    if (Regex.IsMatch(line, @"^\s*(cbuffer\s+\w+|GT_CBUFFER_START\s*\()")) { inBlock = true; continue; }
                    if (inBlock && Regex.IsMatch(line, @"^\s*(\}|GT_CBUFFER_END)")) { inBlock = false; continue; }
                    Match m = Regex.Match(line, @"^\s*(RW)?StructuredBuffer\s*<[^>]+>\s+(_\w+)");
                    if (m.Success) { names.Add(m.Groups[2].Value); continue; }
                    m = Regex.Match(line, inBlock ? @"^\s*(?:float|uint|int|bool)\w*\s+(_\w+)\s*(?:\[[^\]]*\])?\s*;" : @"^(?:float|uint|int|bool)\w*\s+(_\w+)\s*(?:\[[^\]]*\])?\s*;");
                    if (m.Success) names.Add(m.Groups[1].Value);
                }
            }
            return names;
        }

        static string StripComment(string line)
        {
            int c = line.IndexOf("//", StringComparison.Ordinal);
            return c < 0 ? line : line.Substring(0, c);
        }

        static string Rel(string f) => Path.GetRelativePath(PackageRoot.Path, f).Replace('\\', '/');
    }
}
