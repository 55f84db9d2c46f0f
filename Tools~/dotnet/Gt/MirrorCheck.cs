using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Reflection;
using System.Reflection.Metadata;
using System.Reflection.Metadata.Ecma335;
using System.Text;
using System.Text.RegularExpressions;

namespace GregoryTerrain.Rig
{
    /// <summary>
    /// gt mirror: Core's C# and the HLSL are twins file for file (Tools~/development.md, "The mirror"). Each
    /// <c>Shaders/D/X.hlsl</c> of the mirrored folders is paired with <c>Runtime/Core/D/X.cs</c>; the
    /// HLSL's functions are read from its text (comments and preprocessor lines skipped, bodies
    /// skipped by brace depth), the C#'s by reflection over the built Core assembly, each method
    /// placed in its file by the portable PDB. A failure names the file and the function: a function
    /// on one side only, a different parameter shape, or a keyword that is <c>#if</c> in the HLSL and
    /// a runtime bool in C#. Tools~/rig/mirror-allow.txt lists the accepted ones, each with its
    /// reason; an entry that no longer matches anything fails too, so the list stays true.
    /// </summary>
    static class MirrorCheck
    {
        /// <summary>The mirrored folders (Shaders/D and Runtime/Core/D). Pipelines/ and the .compute kernels are stage plumbing: no Core twin.</summary>
        public static readonly string[] Folders = { "Library", "Terrain", "Cache", "Snow", "Grid" };

        public const string AllowListPath = "Tools~/rig/mirror-allow.txt";

        /// <summary>HLSL type to C# type, as the check compares them (the one table of the mapping).</summary>
        static readonly Dictionary<string, string> HlslToCs = new Dictionary<string, string>(StringComparer.Ordinal)
        {
            ["float"] = "float", ["half"] = "float", ["int"] = "int", ["uint"] = "int", ["bool"] = "bool", ["void"] = "void",
            ["float2"] = "Float2", ["float3"] = "Float3", ["float4"] = "Float4", ["float4x4"] = "Float4x4",
            ["TerrainVaryings"] = "TerrainVertexOutput",
            // Core has no integer vectors: an int2, uint2 or bool2 is two C# parameters (int ti, int tj).
            ["int2"] = "int,int", ["uint2"] = "int,int", ["bool2"] = "bool,bool",
        };

        /// <summary>
        /// (HLSL, C#) types that hold the same thing in another form: the settings the GPU packs in a
        /// float4 constant, the layout HLSL derives from the constants, a buffer Core holds as an array.
        /// </summary>
        static readonly HashSet<(string, string)> SameThing = new HashSet<(string, string)>
        {
            ("Float4", "NoiseSettings"), ("Float4", "HeightColorSettings"), ("TileLayout", "TerrainParams"),
            ("StructuredBuffer<float4>", "float"), ("StructuredBuffer<float>", "float"),
        };

        /// <summary>C# (reflection) names of the built-in types; every other type keeps its own name.</summary>
        static readonly Dictionary<Type, string> CsBuiltIn = new Dictionary<Type, string>
        {
            // An integer is an integer: Core counts in int (long where a product could pass 2^31), the GPU in uint.
            [typeof(float)] = "float", [typeof(double)] = "double", [typeof(int)] = "int", [typeof(uint)] = "int",
            [typeof(bool)] = "bool", [typeof(void)] = "void", [typeof(long)] = "int", [typeof(ushort)] = "int", [typeof(byte)] = "int",
        };

        /// <summary>
        /// The package keywords Core models (<c>TerrainKeywords</c> members) and the HLSL keyword of each:
        /// the HLSL reads them only with <c>#if</c>, Core only through a <c>TerrainKeywords</c> parameter.
        /// </summary>
        static readonly Dictionary<string, string> Keywords = new Dictionary<string, string>(StringComparer.Ordinal)
        {
            ["GT_NOISE"] = "Noise", ["GT_HEIGHT_COLOR"] = "HeightColor", ["GT_PAPER_MODE"] = "PaperMode",
            ["GT_SNOW"] = "Snow", ["GT_NOISE_TABLE"] = "NoiseTable",
        };

        /// <summary>C# bool parameter names that carry one of <see cref="Keywords"/> as a runtime value.</summary>
        static readonly Dictionary<string, string> KeywordBools = new Dictionary<string, string>(StringComparer.Ordinal)
        {
            ["tiled"] = "GT_NOISE_TABLE", ["noise"] = "GT_NOISE", ["heightColor"] = "GT_HEIGHT_COLOR",
            ["paperMode"] = "GT_PAPER_MODE", ["snow"] = "GT_SNOW",
        };

        /// <summary>C# parameter types with no HLSL parameter: the HLSL reads the inputs as globals and the keywords with #if.</summary>
        static readonly HashSet<string> GlobalOnGpu = new HashSet<string>(StringComparer.Ordinal) { "TerrainInputs", "TerrainKeywords" };

        /// <summary>C# parameters the HLSL reads from the adapter's camera globals (GT_TessObjectToClip, GT_TessScreenSize).</summary>
        static readonly HashSet<(string, string)> CameraOnGpu = new HashSet<(string, string)> { ("Float4x4", "objectToClip"), ("Float2", "screenSize") };

        public sealed class Parameter
        {
            public string Name, Type, Modifier;   // Type as C# names it (the HLSL's mapped); Modifier: in, out, inout; "any" for a C# array (written or read)
            public string Written;                // the type as its own side writes it
            public bool IsArray;
            public override string ToString() => (Modifier == "in" || Modifier == "any" ? "" : Modifier + " ") + (Written ?? Type) + (IsArray ? "[]" : "") + " " + Name;
        }

        public sealed class Function
        {
            public string Name, Returns, Where;   // Where: file:line
            public string ReturnsWritten;
            public List<Parameter> Parameters = new List<Parameter>();
            public HashSet<string> KeywordsRead = new HashSet<string>(StringComparer.Ordinal);   // HLSL: #if GT_X in the body
            public bool TakesKeywords;                                                          // C#: a TerrainKeywords parameter
            public bool TakesInputs;                                                            // C#: a TerrainInputs parameter or object
            public List<string> KeywordBoolsTaken = new List<string>();                         // C#: "tiled (GT_NOISE_TABLE)"
            public bool IsDouble;
            public string Signature => $"{ReturnsWritten ?? Returns} {Name}({string.Join(", ", Parameters)})";
        }

        /// <summary>One mismatch; <see cref="Kind"/>, <see cref="Stem"/> and <see cref="Name"/> are what an allow-list entry matches.</summary>
        public sealed class Finding
        {
            public string Kind, Stem, Name, Message;
            public override string ToString() => $"{Kind} {Stem} {Name}: {Message}";
        }

        public sealed class AllowEntry
        {
            public string Kind, Stem, Name, Reason;
            public int Line;
            public bool Used;
            public bool Matches(Finding f) => f.Kind == Kind && Glob(Stem, f.Stem) && Glob(Name, f.Name);
            static bool Glob(string pattern, string s) => Regex.IsMatch(s, "^" + Regex.Escape(pattern).Replace("\\*", ".*") + "$");
        }

        public sealed class Report
        {
            public List<string> Pairs = new List<string>();
            public int HlslFunctions, CsFunctions, Matched;
            public List<Finding> Findings = new List<Finding>();
            public List<Finding> Failures = new List<Finding>();
            public List<(Finding finding, AllowEntry entry)> Allowed = new List<(Finding, AllowEntry)>();
            public List<AllowEntry> Stale = new List<AllowEntry>();
            public bool Passed => Failures.Count == 0 && Stale.Count == 0;
        }

        public static int Run(string root)
        {
            if (!File.Exists(Path.Combine(root, "package.json")))
                throw new ArgumentException($"--root {root}: no package.json there (the package root)");
            Report r = Check(root, typeof(TerrainParams).Assembly, Path.Combine(root, AllowListPath));
            Console.WriteLine(Summary(r));
            foreach (Finding f in r.Failures) Console.WriteLine("FAIL " + f);
            foreach (AllowEntry e in r.Stale) Console.WriteLine($"FAIL {AllowListPath}:{e.Line}: '{e.Kind} {e.Stem} {e.Name}' allows nothing now: remove it");
            return r.Passed ? 0 : 1;
        }

        public static string Summary(Report r) =>
            $"mirror: {r.Pairs.Count} twin file pairs, {r.HlslFunctions} HLSL functions, {r.CsFunctions} C# methods, {r.Matched} twins; " +
            $"{r.Findings.Count} mismatches: {r.Allowed.Count} allowed, {r.Failures.Count} failing; {r.Stale.Count} stale allow-list entries";

        /// <summary>Pairs and compares the files under <paramref name="root"/> with the methods of <paramref name="core"/> (its PDB beside it).</summary>
        public static Report Check(string root, Assembly core, string allowListPath)
        {
            var report = new Report();
            CompareKeywordSets(core, report);
            Dictionary<string, List<Function>> cs = CsFunctionsByFile(core);
            foreach (string folder in Folders)
            {
                string dir = Path.Combine(root, "Shaders", folder);
                if (!Directory.Exists(dir)) continue;
                foreach (string hlslPath in Directory.GetFiles(dir, "*.hlsl").OrderBy(p => p, StringComparer.Ordinal))
                {
                    string file = Path.GetFileName(hlslPath);
                    if (file.EndsWith(".cs.hlsl", StringComparison.Ordinal)) continue;   // generated from Core (gt generate, GeneratedContractTests)
                    string stem = folder + "/" + Path.GetFileNameWithoutExtension(file);
                    string csKey = "Runtime/Core/" + stem + ".cs";
                    if (!cs.TryGetValue(csKey, out List<Function> csFunctions))
                    {
                        report.Findings.Add(new Finding { Kind = "hlsl-file", Stem = stem, Name = "*", Message = $"Shaders/{stem}.hlsl has no twin {csKey}" });
                        continue;
                    }
                    report.Pairs.Add(stem);
                    List<Function> hlsl = HlslFunctions(File.ReadAllText(hlslPath), "Shaders/" + stem + ".hlsl");
                    report.HlslFunctions += hlsl.Select(f => f.Name).Distinct().Count();
                    report.CsFunctions += csFunctions.Count;
                    ComparePair(stem, hlsl, csFunctions, report);
                }
            }
            ApplyAllowList(report, ReadAllowList(allowListPath));
            return report;
        }

        /// <summary>The keyword table is Core's TerrainKeywords, member for member: a keyword added on one side fails here.</summary>
        static void CompareKeywordSets(Assembly core, Report report)
        {
            Type keywords = core.GetType("GregoryTerrain.TerrainKeywords", throwOnError: true);
            var members = Enum.GetNames(keywords).Where(n => n != "None").ToList();
            foreach (string m in members.Where(m => !Keywords.ContainsValue(m)))
                report.Findings.Add(new Finding { Kind = "keyword", Stem = "Terrain/TerrainVertex", Name = m, Message = $"TerrainKeywords.{m} has no HLSL keyword in MirrorCheck's table" });
            foreach (var kv in Keywords.Where(kv => !members.Contains(kv.Value)))
                report.Findings.Add(new Finding { Kind = "keyword", Stem = "Terrain/TerrainVertex", Name = kv.Value, Message = $"{kv.Key} has no TerrainKeywords.{kv.Value}" });
        }

        static void ComparePair(string stem, List<Function> hlsl, List<Function> csFunctions, Report report)
        {
            string fileName = stem.Substring(stem.IndexOf('/') + 1);
            var hlslByName = hlsl.GroupBy(f => f.Name).ToDictionary(g => g.Key, g => g.ToList(), StringComparer.Ordinal);
            var twins = new Dictionary<string, List<Function>>(StringComparer.Ordinal);   // HLSL name -> its C# methods
            foreach (Function c in csFunctions)
            {
                string hlslName = TwinName(c, fileName, hlslByName.ContainsKey);
                if (hlslName == null)
                {
                    if (!c.IsDouble)   // the double overloads and helpers are Core's reference: the GPU has no double
                        report.Findings.Add(new Finding { Kind = "cs-only", Stem = stem, Name = c.Name, Message = $"{c.Where}: {c.Signature} has no HLSL twin in Shaders/{stem}.hlsl" });
                    continue;
                }
                if (!twins.TryGetValue(hlslName, out var list)) twins[hlslName] = list = new List<Function>();
                list.Add(c);
            }
            foreach (var (name, variants) in hlslByName.Select(kv => (kv.Key, kv.Value)))
            {
                if (!twins.TryGetValue(name, out var csTwins))
                {
                    report.Findings.Add(new Finding { Kind = "hlsl-only", Stem = stem, Name = name, Message = $"{variants[0].Where}: {variants[0].Signature} has no C# twin in Runtime/Core/{stem}.cs" });
                    continue;
                }
                report.Matched++;
                var floats = csTwins.Where(c => !c.IsDouble).ToList();
                if (floats.Count == 0) floats = csTwins;
                if (!floats.Any(c => variants.Any(h => SameShape(h, c) == null)))
                {
                    Function c = floats[0], h = variants[0];
                    report.Findings.Add(new Finding
                    {
                        Kind = "shape", Stem = stem, Name = name,
                        Message = $"{SameShape(h, c)}: HLSL {h.Where} {h.Signature} vs C# {c.Where} {c.Signature}",
                    });
                }
                string keywordMismatch = KeywordMismatch(variants, floats[0]);
                if (keywordMismatch != null)
                    report.Findings.Add(new Finding { Kind = "keyword", Stem = stem, Name = name, Message = keywordMismatch });
            }
        }

        /// <summary>
        /// Null when the twins switch on the same keywords the same way: the HLSL with #if (in its own body,
        /// not in the functions it calls), the C# through a TerrainKeywords parameter, never a bool.
        /// </summary>
        static string KeywordMismatch(List<Function> variants, Function c)
        {
            if (c.KeywordBoolsTaken.Count > 0)
                return $"C# {c.Where} takes {string.Join(", ", c.KeywordBoolsTaken)} as a runtime bool; HLSL {variants[0].Where} has the keyword compile-time (#if): take TerrainKeywords";
            string read = variants.SelectMany(h => h.KeywordsRead).OrderBy(k => k, StringComparer.Ordinal).FirstOrDefault();
            if (read != null && !c.TakesKeywords)
                return $"HLSL {variants[0].Where} reads {read} with #if; C# {c.Where} {c.Signature} takes no TerrainKeywords";
            return null;
        }

        /// <summary>
        /// The HLSL name of C# method <paramref name="c"/>: its own name, or with the file's name, its
        /// type's name or the file name's first word before it (HLSL has no classes:
        /// <c>GregoryEval.Evaluate</c> is <c>GregoryEvaluate</c>), or the file's name for <c>Evaluate</c>.
        /// </summary>
        static string TwinName(Function c, string fileName, Func<string, bool> exists)
        {
            string firstWord = Regex.Match(fileName, "^[A-Z][a-z0-9]*").Value;
            string typeName = c.Where.Split(':')[2];
            var candidates = new List<string> { c.Name, fileName + c.Name, typeName + c.Name, firstWord + c.Name };
            if (c.Name == "Evaluate") candidates.Add(fileName);
            return candidates.FirstOrDefault(exists);
        }

        /// <summary>Null when <paramref name="h"/> and <paramref name="c"/> take the same shapes, else what differs.</summary>
        static string SameShape(Function h, Function c)
        {
            if (h.Returns != c.Returns && !SameThing.Contains((h.Returns, c.Returns))) return $"returns {h.ReturnsWritten} in HLSL, {c.Returns} in C#";
            // The HLSL's layout is made from the constants, which a C# TerrainInputs carries.
            var hp = h.Parameters.Where(p => !(c.TakesInputs && p.Type == "TileLayout"))
                .SelectMany(p => p.Type.Split(',').Select((t, k) => new Parameter { Name = p.Type.Contains(',') ? p.Name + "." + "xy"[k] : p.Name, Type = t, Written = p.Type.Contains(',') ? null : p.Written, Modifier = p.Modifier, IsArray = p.IsArray }))
                .ToList();
            if (hp.Count != c.Parameters.Count) return $"{hp.Count} parameters in HLSL, {c.Parameters.Count} in C#";
            for (int i = 0; i < hp.Count; i++)
            {
                Parameter a = hp[i], b = c.Parameters[i];
                bool sameModifier = a.Modifier == b.Modifier || b.Modifier == "any"
                    || (b.Modifier == "out" && a.IsArray && a.Modifier == "inout");   // a written Span: out or inout array
                bool sameType = a.Type == b.Type && a.IsArray == b.IsArray
                    || SameThing.Contains((a.Type, b.Type)) && (a.IsArray == b.IsArray || a.Type.StartsWith("StructuredBuffer", StringComparison.Ordinal));
                if (!sameType || !sameModifier)
                    return $"parameter {i + 1} is '{a}' in HLSL, '{b}' in C#";
            }
            return null;
        }

        // ---- HLSL ----

        // The end of the text before a top-level '{': what precedes (attributes, a macro without ';') does not matter.
        static readonly Regex FunctionHeader = new Regex(
            @"(?:^|\s)(?<ret>\w+)\s+(?<name>\w+)\s*\((?<params>[^()]*)\)\s*(?::\s*\w+\s*)?$",
            RegexOptions.Singleline);

        static readonly Regex HlslParameter = new Regex(
            @"^(?<mods>(?:(?:in|out|inout|uniform|const|precise|nointerpolation|linear|centroid|noperspective|sample)\s+)*)(?<type>\w+(?:<[^>]*>)?)\s+(?<name>\w+)\s*(?:\[(?<len>[^\]]*)\])?\s*(?::\s*\w+)?\s*(?:=.*)?$",
            RegexOptions.Singleline);

        /// <summary>The functions defined in one HLSL text (not its includes); both branches of an #if count.</summary>
        public static List<Function> HlslFunctions(string text, string path)
        {
            string code = CodeOnly(text, out List<(int line, string directive)> directives);
            var functions = new List<Function>();
            int depth = 0, headerStart = 0;
            for (int i = 0; i < code.Length; i++)
            {
                char ch = code[i];
                if (ch == '{')
                {
                    if (depth == 0)
                    {
                        string header = code.Substring(headerStart, i - headerStart);
                        Match m = FunctionHeader.Match(header);
                        if (m.Success && m.Groups["ret"].Value != "struct")
                        {
                            int end = MatchingBrace(code, i);
                            int startLine = LineOf(code, headerStart + m.Groups["ret"].Index);
                            var f = new Function
                            {
                                Name = m.Groups["name"].Value, Returns = HlslType(m.Groups["ret"].Value), ReturnsWritten = m.Groups["ret"].Value,
                                Where = $"{path}:{startLine}",
                            };
                            f.Parameters.AddRange(HlslParameters(m.Groups["params"].Value, path, f.Name));
                            int lastLine = LineOf(code, end);
                            foreach (var (line, directive) in directives)
                                if (line > startLine && line < lastLine && Regex.IsMatch(directive, @"^#\s*(el)?if"))
                                    foreach (Match k in Regex.Matches(directive, @"\bGT_\w+"))
                                        if (Keywords.ContainsKey(k.Value)) f.KeywordsRead.Add(k.Value);
                            functions.Add(f);
                            i = end;
                            headerStart = i + 1;
                            continue;
                        }
                    }
                    depth++;
                }
                else if (ch == '}') { if (--depth == 0) headerStart = i + 1; }
                else if (ch == ';' && depth == 0) headerStart = i + 1;
            }
            return functions;
        }

        static IEnumerable<Parameter> HlslParameters(string list, string path, string function)
        {
            if (list.Trim().Length == 0 || list.Trim() == "void") yield break;
            foreach (string raw in list.Split(','))
            {
                Match m = HlslParameter.Match(raw.Trim());
                if (!m.Success) throw new FormatException($"{path}: {function}: cannot read the parameter '{raw.Trim()}'");
                string[] mods = m.Groups["mods"].Value.Split(new[] { ' ', '\t', '\n' }, StringSplitOptions.RemoveEmptyEntries);
                yield return new Parameter
                {
                    Name = m.Groups["name"].Value, Type = HlslType(m.Groups["type"].Value), Written = m.Groups["type"].Value, IsArray = m.Groups["len"].Success,
                    Modifier = mods.Contains("inout") || (mods.Contains("in") && mods.Contains("out")) ? "inout" : mods.Contains("out") ? "out" : "in",
                };
            }
        }

        static string HlslType(string t) => HlslToCs.TryGetValue(t, out string cs) ? cs : t;

        /// <summary>The text without comments and preprocessor lines (blanked, so offsets keep their line), and the directives by line.</summary>
        static string CodeOnly(string text, out List<(int, string)> directives)
        {
            directives = new List<(int, string)>();
            text = text.Replace("\r\n", "\n");
            var sb = new StringBuilder(text.Length);
            for (int i = 0; i < text.Length; i++)
            {
                if (text[i] == '"')   // a string (an #error's text, an attribute's argument) is kept whole: "/*" inside starts no comment
                {
                    int close = text.IndexOf('"', i + 1);
                    close = close < 0 ? text.Length - 1 : close;
                    sb.Append(text, i, close - i + 1);
                    i = close;
                    continue;
                }
                if (text[i] == '/' && i + 1 < text.Length && text[i + 1] == '/')
                    while (i < text.Length && text[i] != '\n') i++;
                else if (text[i] == '/' && i + 1 < text.Length && text[i + 1] == '*')
                {
                    int end = text.IndexOf("*/", i + 2, StringComparison.Ordinal);
                    end = end < 0 ? text.Length : end + 2;
                    for (; i < end; i++) sb.Append(text[i] == '\n' ? '\n' : ' ');
                    i--;
                    continue;
                }
                if (i < text.Length) sb.Append(text[i]);
            }
            string[] lines = sb.ToString().Split('\n');
            for (int n = 0; n < lines.Length; n++)
            {
                if (!lines[n].TrimStart().StartsWith("#", StringComparison.Ordinal)) continue;
                int first = n;
                string directive = lines[n].Trim();
                lines[n] = "";
                while (directive.EndsWith("\\", StringComparison.Ordinal) && n + 1 < lines.Length)
                {
                    directive = directive.TrimEnd('\\') + " " + lines[++n].Trim();
                    lines[n] = "";
                }
                directives.Add((first + 1, directive));
            }
            return string.Join("\n", lines);
        }

        static int MatchingBrace(string code, int open)
        {
            int depth = 0;
            for (int i = open; i < code.Length; i++)
            {
                if (code[i] == '{') depth++;
                else if (code[i] == '}' && --depth == 0) return i;
            }
            throw new FormatException("unbalanced braces");
        }

        static int LineOf(string code, int offset)
        {
            int line = 1;
            for (int i = 0; i < offset && i < code.Length; i++) if (code[i] == '\n') line++;
            return line;
        }

        // ---- C# ----

        static readonly Regex LocalFunction = new Regex(@"^<\w+>g__(?<name>\w+)\|");

        /// <summary>Core's methods by source file ("Runtime/Core/D/X.cs"), from reflection and the portable PDB beside the assembly.</summary>
        public static Dictionary<string, List<Function>> CsFunctionsByFile(Assembly core)
        {
            string pdbPath = Path.ChangeExtension(core.Location, ".pdb");
            if (!File.Exists(pdbPath)) throw new FileNotFoundException($"{pdbPath}: the Core assembly's portable PDB (it places each method in its file)", pdbPath);
            var byFile = new Dictionary<string, List<Function>>(StringComparer.Ordinal);
            using FileStream stream = File.OpenRead(pdbPath);
            using MetadataReaderProvider provider = MetadataReaderProvider.FromPortablePdbStream(stream);
            MetadataReader pdb = provider.GetMetadataReader();
            foreach (MethodDebugInformationHandle h in pdb.MethodDebugInformation)
            {
                MethodDebugInformation info = pdb.GetMethodDebugInformation(h);
                var points = info.GetSequencePoints().Where(p => !p.IsHidden).ToList();
                if (points.Count == 0) continue;
                string document = pdb.GetString(pdb.GetDocument(points[0].Document).Name).Replace('\\', '/');
                int at = document.IndexOf("/Runtime/Core/", StringComparison.Ordinal);
                if (at < 0) continue;
                MethodBase method = core.ManifestModule.ResolveMethod(MetadataTokens.GetToken(h.ToDefinitionHandle()));
                Function f = CsFunction(method, document.Substring(at + 1), points.Min(p => p.StartLine));
                if (f == null) continue;
                string file = document.Substring(at + 1);
                if (!byFile.TryGetValue(file, out var list)) byFile[file] = list = new List<Function>();
                list.Add(f);
            }
            return byFile;
        }

        /// <summary>The mirror's view of one method; null for what has no HLSL counterpart by nature (constructors, accessors, operators, lambdas, object's overrides).</summary>
        static Function CsFunction(MethodBase method, string file, int line)
        {
            if (!(method is MethodInfo m) || m.IsSpecialName || m.DeclaringType.Name.Contains('<')) return null;
            string name = m.Name;
            if (name.Contains('<'))
            {
                Match local = LocalFunction.Match(name);
                if (!local.Success) return null;   // a lambda
                name = local.Groups["name"].Value;
            }
            if (name == "Equals" || name == "GetHashCode" || name == "ToString" || m.GetBaseDefinition() != m) return null;
            var f = new Function { Name = name, Returns = CsType(m.ReturnType, out _, out _), Where = $"{file}:{line}:{m.DeclaringType.Name}" };
            Type self = m.DeclaringType;
            if (self.Name == "TerrainInputs") f.TakesInputs = true;
            else if (!m.IsStatic)   // an instance method's object is its HLSL twin's first parameter (in or inout: a struct's method may write it)
                f.Parameters.Add(new Parameter { Name = "this", Type = self.Name, Modifier = self.IsValueType ? "any" : "in" });
            foreach (ParameterInfo p in m.GetParameters())
            {
                Type t = p.ParameterType;
                string modifier = "in";
                if (t.IsByRef)
                {
                    modifier = p.IsOut ? "out" : p.IsIn ? "in" : "inout";
                    t = t.GetElementType();
                }
                if (t.Name.Contains('<') && !t.IsGenericType) continue;   // a local function's closure
                string type = CsType(t, out bool isArray, out string arrayAccess);
                if (type == "TerrainKeywords") f.TakesKeywords = true;
                if (type == "TerrainInputs") f.TakesInputs = true;
                if (GlobalOnGpu.Contains(type) || CameraOnGpu.Contains((type, p.Name))) continue;
                if (type == "bool" && KeywordBools.TryGetValue(p.Name, out string keyword))
                {
                    f.KeywordBoolsTaken.Add($"'{p.Name}' ({keyword})");
                    continue;
                }
                if (isArray && modifier == "in") modifier = arrayAccess;
                f.Parameters.Add(new Parameter { Name = p.Name, Type = type, IsArray = isArray, Modifier = modifier });
            }
            f.IsDouble = f.Returns.Contains("ouble") || f.Parameters.Any(p => p.Type.Contains("ouble"));
            f.KeywordBoolsTaken = f.KeywordBoolsTaken.Select(b => b.Replace("'", "")).ToList();
            return f;
        }

        static string CsType(Type t, out bool isArray, out string access)
        {
            isArray = false;
            access = "in";
            if (t.IsArray) { isArray = true; access = "any"; t = t.GetElementType(); }
            else if (t.IsGenericType && (t.GetGenericTypeDefinition() == typeof(Span<>) || t.GetGenericTypeDefinition() == typeof(ReadOnlySpan<>)))
            {
                isArray = true;
                access = t.GetGenericTypeDefinition() == typeof(Span<>) ? "out" : "in";
                t = t.GetGenericArguments()[0];
            }
            return CsBuiltIn.TryGetValue(t, out string name) ? name : t.Name;
        }

        // ---- allow-list ----

        /// <summary>Lines "KIND STEM NAME -- REASON" (# comments); STEM and NAME may hold '*'. Throws naming the line of a malformed entry.</summary>
        public static List<AllowEntry> ReadAllowList(string path)
        {
            var entries = new List<AllowEntry>();
            string[] lines = File.ReadAllLines(path);
            for (int n = 0; n < lines.Length; n++)
            {
                string line = lines[n].Trim();
                if (line.Length == 0 || line.StartsWith("#", StringComparison.Ordinal)) continue;
                Match m = Regex.Match(line, @"^(?<kind>hlsl-file|cs-only|hlsl-only|shape|keyword)\s+(?<stem>\S+)\s+(?<name>\S+)\s+--\s+(?<reason>\S.{9,})$");
                if (!m.Success)
                    throw new FormatException($"{path}:{n + 1}: '{line}' is not 'KIND STEM NAME -- REASON' (KIND hlsl-file, cs-only, hlsl-only, shape or keyword; a reason of 10 characters or more)");
                entries.Add(new AllowEntry { Kind = m.Groups["kind"].Value, Stem = m.Groups["stem"].Value, Name = m.Groups["name"].Value, Reason = m.Groups["reason"].Value, Line = n + 1 });
            }
            return entries;
        }

        static void ApplyAllowList(Report report, List<AllowEntry> entries)
        {
            foreach (Finding f in report.Findings)
            {
                AllowEntry e = entries.FirstOrDefault(a => a.Matches(f));
                if (e == null) report.Failures.Add(f);
                else { e.Used = true; report.Allowed.Add((f, e)); }
            }
            report.Stale.AddRange(entries.Where(e => !e.Used));
        }
    }
}
