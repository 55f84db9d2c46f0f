using System;
using System.Collections.Generic;
using System.Globalization;
using System.Text;
using System.Threading;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    /// <summary>
    /// The hostile-input suite over Core's entry points (issue 25): the grid JSON reader, grid
    /// validation, Core's public calls, the fitter's entry and the renderer-settings validation.
    /// Each generated case must end with a clear refusal (the field and the value named, the message
    /// short, nothing changed) or a documented acceptance, within a per-case watchdog. The CLI's
    /// cases are in HostileCliTests.cs. The tally is printed at the end. A generated audit with a
    /// watchdog thread a case is the rig's, not a package test: it lives here, not in Tests/.
    /// </summary>
    [TestFixture]
    public class HostileInputTests
    {
        const int TimeoutMs = 10000;
        static readonly HostileTally Tally = new HostileTally();

        [OneTimeTearDown]
        public void Report() => TestContext.Progress.WriteLine("hostile Core cases: " + Tally);

        [TestCaseSource(nameof(Cases))]
        public void Hostile(HostileCase c) => Tally.Assert(c, TimeoutMs);

        static string N(double d) => d.ToString("R", CultureInfo.InvariantCulture);

        // ---- a small good file and its parts, to mutate one at a time
        static readonly PatchGrid GoodGrid = HardCaseGrids.Fitted(2, 1, 3, 9);

        static string Patches(PatchGrid g, int patch = -1, int slot = -1, int coord = -1, string value = null)
        {
            var sb = new StringBuilder("[");
            for (int p = 0; p < g.PatchCount; p++)
            {
                sb.Append(p == 0 ? "[" : ",[");
                for (int k = 0; k < 20; k++)
                {
                    if (k > 0) sb.Append(',');
                    Double3 c = g.Patches[p][k];
                    string[] xyz = { PatchGridJson.Number(c.x), PatchGridJson.Number(c.y), PatchGridJson.Number(c.z) };
                    if (p == patch && k == slot) xyz[coord] = value;
                    sb.Append('[').Append(string.Join(",", xyz)).Append(']');
                }
                sb.Append(']');
            }
            return sb.Append(']').ToString();
        }

        static readonly string GoodPatches = Patches(GoodGrid);

        static string Json(string format = "\"gregory-terrain-grid\"", string version = "1", string columns = "2", string rows = "1",
                           string xLines = "[0,0.5,1]", string yLines = "[0,1]", string patches = null, string extra = "")
        {
            var members = new List<string>();
            if (format != null) members.Add("\"format\":" + format);
            if (version != null) members.Add("\"version\":" + version);
            if (columns != null) members.Add("\"columns\":" + columns);
            if (rows != null) members.Add("\"rows\":" + rows);
            if (xLines != null) members.Add("\"xLines\":" + xLines);
            if (yLines != null) members.Add("\"yLines\":" + yLines);
            members.Add("\"patches\":" + (patches ?? GoodPatches));
            return "{" + string.Join(",", members) + extra + "}";
        }

        static HostileCase BadJson(string name, string json, params string[] mentions) =>
            HostileCase.Refuse<FormatException>("json", name, () => PatchGridJson.Read(json), mentions);

        static HostileCase GoodJson(string name, string why, string json) =>
            HostileCase.Accept("json", name, why, () => PatchGridJson.Read(json));

        static string Snapshot(PatchGrid g)
        {
            var sb = new StringBuilder();
            foreach (double x in g.XLines) sb.Append(N(x)).Append(' ');
            foreach (double y in g.YLines) sb.Append(N(y)).Append(' ');
            foreach (GregoryPatch p in g.Patches)
                foreach (Double3 c in p.Points) sb.Append(N(c.x)).Append(',').Append(N(c.y)).Append(',').Append(N(c.z)).Append(' ');
            return sb.ToString();
        }

        public static IEnumerable<TestCaseData> Cases()
        {
            var all = new List<HostileCase>();
            all.AddRange(JsonCases());
            all.AddRange(GridCases());
            all.AddRange(CoreCallCases());
            all.AddRange(FitterCases());
            all.AddRange(SettingsCases());
            for (int k = 0; k < all.Count; k++)
                yield return new TestCaseData(all[k]).SetArgDisplayNames(k.ToString("D3", CultureInfo.InvariantCulture) + " " + all[k]);
        }

        // ---- 1. the grid JSON reader
        static IEnumerable<HostileCase> JsonCases()
        {
            yield return GoodJson("the good file", "control: the base every mutation starts from", Json());
            string[] names = { "format", "version", "columns", "rows", "xLines", "yLines" };
            foreach (string n in names)
            {
                string json = Json().Replace("\"" + n + "\":", "\"" + n + "_gone\":");
                yield return BadJson("misspelt member " + n, json, n + "_gone", "not part of the format");
            }
            yield return BadJson("missing format", Json(format: null), "format", "missing");
            yield return BadJson("missing version", Json(version: null), "version", "missing");
            yield return BadJson("missing columns", Json(columns: null), "columns", "missing");
            yield return BadJson("missing rows", Json(rows: null), "rows", "missing");
            yield return BadJson("missing xLines", Json(xLines: null), "xLines", "missing");
            yield return BadJson("missing yLines", Json(yLines: null), "yLines", "missing");
            yield return BadJson("duplicate columns", Json(extra: ",\"columns\":5"), "columns", "twice");
            yield return BadJson("duplicate format", Json(extra: ",\"format\":\"x\""), "format", "twice");
            yield return BadJson("duplicate patches", Json(extra: ",\"patches\":[]"), "patches", "twice");
            yield return BadJson("unknown member", Json(extra: ",\"comment\":\"hi\""), "comment", "not part of the format");

            // wrong kinds for each member
            string[] wrong = { "\"text\"", "true", "null", "{}", "[]", "7" };
            foreach (string n in new[] { "format", "version", "columns", "rows", "xLines", "yLines", "patches" })
                foreach (string w in wrong)
                {
                    bool numberMember = n == "version" || n == "columns" || n == "rows";
                    bool arrayMember = n == "xLines" || n == "yLines" || n == "patches";
                    if ((w == "7" && numberMember) || (w == "[]" && arrayMember) || (w == "\"text\"" && n == "format")) continue;
                    string json = n == "format" ? Json(format: w) : n == "version" ? Json(version: w) : n == "columns" ? Json(columns: w)
                        : n == "rows" ? Json(rows: w) : n == "xLines" ? Json(xLines: w) : n == "yLines" ? Json(yLines: w) : Json(patches: w);
                    yield return BadJson($"{n} = {w}", json, n);
                }

            // numbers a reader can get wrong, in the grid lines and in a control point
            string[] badNumbers = { "1e400", "-1e400", "NaN", "Infinity", "-Infinity", "0x10", "1.", ".5", "--1", "1e", "+1", "1_000", "١" };
            foreach (string b in badNumbers)
            {
                yield return BadJson($"xLines[1] = {b}", Json(xLines: $"[0,{b},1]"), "xLines[1]");
                yield return BadJson($"control point = {b}", Json(patches: Patches(GoodGrid, 1, 6, 2, b)), "patches[1]", "[6][2]");
            }
            yield return BadJson("control point 1e39 (beyond float)", Json(patches: Patches(GoodGrid, 1, 6, 2, "1e39")), "patch (1, 0) slot 6", "1E+39", "float32");
            yield return BadJson("control point -3.5e38 (beyond float)", Json(patches: Patches(GoodGrid, 0, 5, 0, "-3.5e38")), "patch (0, 0) slot 5", "-3.5E+38", "float32");
            yield return GoodJson("control point 3.4e38 (inside float)", "float32's largest values are drawable; the edge is 3.4028235e38", Json(patches: Patches(GoodGrid, 0, 5, 2, "3.4e38")));
            yield return GoodJson("control point -0.0", "negative zero is a number like any other", Json(patches: Patches(GoodGrid, 0, 5, 2, "-0.0")));
            yield return GoodJson("control point 1E0", "JSON exponents in either case", Json(patches: Patches(GoodGrid, 0, 5, 2, "1E0")));
            yield return BadJson("control point with 1001 digits", Json(patches: Patches(GoodGrid, 0, 5, 2, "1" + new string('0', 1000))), "longer than 1000");

            // counts and shapes
            foreach (string n in new[] { "0", "-1", "1.5", "3e9", "-3e9", "1e400" })
            {
                yield return BadJson("columns = " + n, Json(columns: n), "columns", n);
                yield return BadJson("rows = " + n, Json(rows: n), "rows", n);
            }
            yield return BadJson("version = 2", Json(version: "2"), "version", "2");
            yield return BadJson("version = 1.5", Json(version: "1.5"), "version", "1.5");
            yield return BadJson("columns 100000 x rows 100000 (beyond the GPU)", Json(columns: "100000", rows: "100000"), "columns * rows", "10000000000");
            yield return BadJson("columns 4096 x rows 4096 (over 2 GiB of control points)", Json(columns: "4096", rows: "4096"), "columns * rows", "16777216");
            yield return BadJson("columns 3 with 2 patches", Json(columns: "3", xLines: "[0,0.3,0.6,1]"), "patches", "has 2 patches");
            yield return BadJson("xLines too short", Json(xLines: "[0,1]"), "xLines", "has 2 numbers");
            yield return BadJson("xLines too long", Json(xLines: "[0,0.25,0.5,1]"), "xLines", "has 4 numbers");
            yield return BadJson("xLines decreasing", Json(xLines: "[0,0.7,0.6]"), "xLines");
            yield return BadJson("xLines not reaching 1", Json(xLines: "[0,0.5,0.9]"), "xLines[2]", "0.9");
            yield return BadJson("xLines starting at -0.1", Json(xLines: "[-0.1,0.5,1]"), "xLines[0]", "-0.1");
            yield return BadJson("xLines collapsing in float", Json(xLines: "[0,1e-50,1]"), "xLines[1]", "same float");
            yield return BadJson("a patch of 19 points", Json(patches: GoodPatches.Replace("]],[[", "]],[").Replace("[[[", "[[")), "patches");
            yield return BadJson("a point of 2 numbers", Json(patches: Patches(GoodGrid, 0, 3, 2, "0").Replace(",0]", "]")), "need 3");
            yield return BadJson("a point of 4 numbers", Json(patches: Patches(GoodGrid, 0, 3, 2, "0,0")), "more than 3");
            yield return BadJson("a point that is a number", Json(patches: "[7]"), "patches[0]", "expected a array");
            yield return BadJson("empty patches", Json(patches: "[]"), "patches", "has 0 patches");
            yield return BadJson("mismatched shared edge", Json(patches: Patches(GoodGrid, 0, 13, 2, "0.123")), "slot 13", "identical");

            // syntax
            string good = Json();
            foreach (int cut in new[] { 0, 1, 2, 10, 30, 60, 100, good.Length / 2, good.Length - 3, good.Length - 1 })
                yield return BadJson($"truncated at {cut} of {good.Length}", good.Substring(0, cut), cut == 0 ? "expected an object" : "truncated");
            yield return BadJson("trailing comma", Json(extra: ","), "expected a string");
            yield return BadJson("trailing garbage", good + "x", "after the end of the document");
            yield return BadJson("two documents", good + good, "after the end of the document");
            yield return BadJson("comment", "//c\n" + good, "expected an object");
            yield return BadJson("single quotes", good.Replace("\"format\"", "'format'"), "expected a string");
            yield return BadJson("a byte-order mark in a string read", "\uFEFF" + good, "expected an object");
            yield return BadJson("an array document", "[" + good + "]", "expected an object");
            yield return BadJson("empty text", "", "expected an object");
            yield return BadJson("only spaces", "   \n\t ", "expected an object");
            yield return BadJson("a control character in a string", good.Replace("gregory-terrain-grid", "gregory\u0001"), "control character");
            yield return BadJson("a bad escape", good.Replace("gregory-terrain-grid", "gregory\\q"), "bad escape");
            yield return BadJson("a bad \\u escape", good.Replace("gregory-terrain-grid", "\\uZZZZ"), "hex digit");
            yield return BadJson("a string cut inside an escape", "{\"format\":\"\\", "truncated");
            yield return GoodJson("an escaped format name", "JSON escapes are decoded before comparing", good.Replace("gregory-terrain-grid", "gregory\\u002dterrain-grid"));
            yield return GoodJson("members in another order", "RFC 8259 objects are unordered", "{" + "\"patches\":" + GoodPatches + ",\"rows\":1,\"columns\":2,\"yLines\":[0,1],\"xLines\":[0,0.5,1],\"version\":1,\"format\":\"gregory-terrain-grid\"}");
            yield return GoodJson("CRLF and tabs", "JSON white space", good.Replace(",", ",\r\n\t"));

            // nesting and size: refused at the first extra bracket, without recursion or a big allocation
            yield return BadJson("1,000,000 nested arrays", new string('[', 1000000) + new string(']', 1000000), "expected an object");
            yield return BadJson("deep nesting in patches", Json(patches: new string('[', 100000) + new string(']', 100000)), "expected a number");
            yield return BadJson("deep nesting in xLines", Json(xLines: new string('[', 100000) + new string(']', 100000)), "xLines[0]", "expected a number");
            yield return BadJson("deep nesting as a member value", Json(extra: ",\"x\":" + new string('{', 100000)), "\"x\"", "not part of the format");
            string huge = new string('g', 20000000);
            yield return BadJson("a 20 MB format string", Json(format: "\"" + huge + "\""), "format", "20000000 characters");
            yield return BadJson("a 20 MB member name", "{\"" + huge + "\":1}", "20000000 characters", "not part of the format");
            yield return BadJson("a 20 MB number", Json(xLines: "[0," + new string('5', 20000000) + ",1]"), "longer than 1000");
            yield return HostileCase.Refuse<ArgumentNullException>("json", "null text", () => PatchGridJson.Read((string)null), "json");
            yield return HostileCase.Refuse<System.IO.IOException>("json", "a folder as the file", () => PatchGridJson.ReadFile(System.IO.Path.GetTempPath()), "folder");
            yield return HostileCase.Refuse<System.IO.FileNotFoundException>("json", "a missing file", () => PatchGridJson.ReadFile("/no/such/grid.json"), "/no/such/grid.json", "does not exist");
            yield return HostileCase.Refuse<ArgumentException>("json", "an empty path", () => PatchGridJson.ReadFile(""), "path");
        }

        // ---- 2. grid validation (PatchGrid.Validate, the rule every entry point shares)
        static IEnumerable<HostileCase> GridCases()
        {
            double[] values = { double.NaN, double.PositiveInfinity, 1e39, -1e39, 3.4028236e38 };
            for (int slot = 0; slot < 20; slot++)
            {
                double v = values[slot % values.Length];
                int s = slot, axis = slot % 3;
                PatchGrid g = HardCaseGrids.Fitted(3, 3, 2, 17);
                var p = g.Patches[4][s];
                g.Patches[4][s] = axis == 0 ? new Double3(v, p.y, p.z) : axis == 1 ? new Double3(p.x, v, p.z) : new Double3(p.x, p.y, v);
                string shown = double.IsNaN(v) ? "NaN" : double.IsInfinity(v) ? "Infinity" : v.ToString("R", CultureInfo.InvariantCulture).Replace("E+", "E+");
                yield return HostileCase.Refuse<ArgumentException>("grid", $"patch 4 slot {s} axis {axis} = {shown}", () => g.Validate(), "patch (1, 1)", "slot " + s)
                    .WithState(() => Snapshot(g));
            }
            foreach (double[] xl in new[] { new[] { 0.0, 0.5, 0.5, 1.0 }, new[] { 0.0, 0.6, 0.4, 1.0 }, new[] { 0.1, 0.5, 0.7, 1.0 },
                                            new[] { 0.0, 0.5, 0.7, 0.99 }, new[] { 0.0, double.NaN, 0.7, 1.0 }, new[] { 0.0, 0.5, 0.5 + 1e-12, 1.0 },
                                            new[] { 0.0, 1e-50, 0.5, 1.0 }, new[] { -0.0, 0.5, 0.7, 1.0 } })
            {
                bool acceptable = xl[0] == 0 && BitConverter.DoubleToInt64Bits(xl[0]) != 0; // -0.0 == 0: accepted
                PatchGrid g = PatchGrid.CreateFlat(3, 1, xl, new[] { 0.0, 1.0 });
                string name = "xLines " + string.Join(",", Array.ConvertAll(xl, N));
                if (acceptable)
                    yield return HostileCase.Accept("grid", name, "-0.0 equals 0 (the grid starts at the square's edge)", () => g.Validate());
                else
                    yield return HostileCase.Refuse<ArgumentException>("grid", name, () => g.Validate(), "xLines").WithState(() => Snapshot(g));
            }
            {
                PatchGrid g = HardCaseGrids.Fitted(3, 3, 2, 17);
                g.Patches[0][12] = g.Patches[0][12] + new Double3(0, 0, 1e-9);
                yield return HostileCase.Refuse<ArgumentException>("grid", "shared edge off by 1e-9", () => g.Validate(), "slot 12", "identical").WithState(() => Snapshot(g));
            }
            yield return HostileCase.Refuse<ArgumentException>("grid", "patches.Length 3 for 2 x 2", () => new PatchGrid(2, 2, PatchGrid.UniformLines(2), PatchGrid.UniformLines(2), new GregoryPatch[3]), "patches.Length", "3");
            yield return HostileCase.Refuse<ArgumentException>("grid", "a null patch", () => new PatchGrid(1, 1, PatchGrid.UniformLines(1), PatchGrid.UniformLines(1), new GregoryPatch[1]), "patches[0]", "null");
            yield return HostileCase.Refuse<ArgumentNullException>("grid", "null xLines", () => new PatchGrid(1, 1, null, PatchGrid.UniformLines(1), new[] { new GregoryPatch() }), "xLines");
            yield return HostileCase.Refuse<ArgumentException>("grid", "columns 0", () => PatchGrid.CreateFlat(0, 3), "columns", "0");
            yield return HostileCase.Refuse<ArgumentException>("grid", "rows -7", () => PatchGrid.CreateFlat(3, -7), "rows", "-7");
            yield return HostileCase.Refuse<ArgumentException>("grid", "columns * rows beyond int", () => PatchGrid.CreateFlat(65536, 65536), "columns * rows", "4294967296");
            yield return HostileCase.Refuse<ArgumentException>("grid", "CheckSize 8192 x 4096", () => GpuLayout.CheckSize(8192, 4096), "columns * rows", "33554432");
            yield return HostileCase.Refuse<ArgumentException>("grid", "CheckSize 2600 x 2600 (over 2 GiB)", () => GpuLayout.CheckSize(2600, 2600), "6760000", "2 GiB");
            yield return HostileCase.Accept("grid", "CheckSize 2048 x 2048", "4M patches fit the 2 GiB control-point buffer", () => GpuLayout.CheckSize(2048, 2048));

            // the asset's serialized fields: the same rules through PatchGrid.SerializedDataError
            foreach (var (name, cols, rws, cps, mentions) in AssetCases())
            {
                double[] data = cps;
                int n = cols, m = rws;
                yield return HostileCase.Refuse<ArgumentException>("asset", name, () =>
                {
                    string e = PatchGrid.SerializedDataError(n, m, PatchGrid.UniformLines(Math.Min(n, 4)), PatchGrid.UniformLines(Math.Min(m, 4)), data);
                    if (e != null) throw new ArgumentException(e);
                }, mentions).WithState(() => data == null ? "" : string.Join(",", Array.ConvertAll(data, N)));
            }

            // geometry a valid grid may hold: loaded, with a warning naming the patch
            {
                PatchGrid flipped = Flipped();
                yield return HostileCase.Accept("geometry", "a flipped patch", "valid data; drawn inside out, so it is reported as a warning",
                    () => flipped.Validate(), () => string.Join("\n", PatchGridGeometry.Warnings(flipped)), "patch 0 (0, 0)", "pointing down");
                PatchGrid zero = Collapsed();
                yield return HostileCase.Accept("geometry", "an all-zero patch grid", "valid data; nothing to draw, so it is reported as a warning",
                    () => zero.Validate(), () => string.Join("\n", PatchGridGeometry.Warnings(zero)), "patch 0 (0, 0)", "zero normal");
                PatchGrid many = Collapsed(6, 5);
                yield return HostileCase.Accept("geometry", "30 collapsed patches", "valid data; the warnings list 20 patches and count the rest",
                    () => many.Validate(), () => string.Join("\n", PatchGridGeometry.Warnings(many)), "patch 19 (1, 3)", "and 10 more");
                PatchGrid sound = HardCaseGrids.Fitted(3, 3, 2, 17);
                yield return HostileCase.Accept("geometry", "a sound grid", "no warnings",
                    () => { if (PatchGridGeometry.Warnings(sound).Count != 0) throw new InvalidOperationException("warnings on a sound grid"); });
            }
        }

        static IEnumerable<(string, int, int, double[], string[])> AssetCases()
        {
            double[] Flat(int n, int m)
            {
                PatchGrid g = PatchGrid.CreateFlat(n, m);
                var d = new double[n * m * 60];
                for (int p = 0; p < g.PatchCount; p++)
                    for (int k = 0; k < 20; k++) { Double3 c = g.Patches[p][k]; d[p * 60 + 3 * k] = c.x; d[p * 60 + 3 * k + 1] = c.y; d[p * 60 + 3 * k + 2] = c.z; }
                return d;
            }
            double[] a = Flat(2, 2); a[60 + 3 * 7 + 2] = 1e39;
            yield return ("a 1e39 height", 2, 2, a, new[] { "patch (1, 0) slot 7", "1E+39", "float32" });
            double[] b = Flat(2, 2); b[3 * 12 + 2] = 0.5;
            yield return ("a torn shared edge", 2, 2, b, new[] { "slot 12", "identical" });
            yield return ("too few control points", 2, 2, new double[10], new[] { "controlPoints.Length", "10" });
            yield return ("null control points", 2, 2, null, new[] { "controlPoints.Length", "0" });
            yield return ("100000 x 100000 patches", 100000, 100000, new double[60], new[] { "columns * rows", "10000000000" });
            double[] c2 = Flat(2, 2); c2[5] = double.NaN;
            yield return ("a NaN point", 2, 2, c2, new[] { "slot 1", "NaN" });
        }

        /// <summary>A 1 x 1 flat grid whose x runs backwards in u: the normal points down.</summary>
        static PatchGrid Flipped()
        {
            PatchGrid g = PatchGrid.CreateFlat(1, 1);
            for (int k = 0; k < 20; k++) { Double3 c = g.Patches[0][k]; g.Patches[0][k] = new Double3(c.y, c.x, c.z); }
            return g;
        }

        /// <summary>A grid whose control points are all zero.</summary>
        static PatchGrid Collapsed(int columns = 1, int rows = 1)
        {
            PatchGrid g = PatchGrid.CreateFlat(columns, rows);
            foreach (GregoryPatch p in g.Patches) for (int k = 0; k < 20; k++) p[k] = new Double3(0, 0, 0);
            return g;
        }

        // ---- 3. Core's public calls
        static IEnumerable<HostileCase> CoreCallCases()
        {
            PatchGrid g = HardCaseGrids.Fitted(3, 3, 2, 17);
            foreach (int s in new[] { int.MinValue, -5, 0, 1, 4098, 200000000, int.MaxValue })
                yield return HostileCase.Refuse<ArgumentException>("measure", $"samples per edge {s}", () => ContinuityMeasure.MaxNormalAngleDegrees(g, s), "samplesPerEdge", s.ToString(CultureInfo.InvariantCulture), "4097")
                    .WithState(() => Snapshot(g));
            foreach (int s in new[] { 2, 4097 })
                yield return HostileCase.Accept("measure", $"samples per edge {s}", "inside [2, 4097]", () => ContinuityMeasure.Measure(g, s));
            yield return HostileCase.Refuse<ArgumentNullException>("measure", "null grid", () => ContinuityMeasure.Measure(null), "grid");
            var cancelled = new CancellationTokenSource();
            cancelled.Cancel();
            yield return HostileCase.Refuse<OperationCanceledException>("measure", "cancelled before it starts", () => ContinuityMeasure.Measure(g, 65, null, cancelled.Token), "cancel")
                .WithState(() => Snapshot(g));
            PatchGrid big = PatchGrid.CreateFlat(256, 256);
            yield return HostileCase.Accept("measure", "256 x 256 cancelled from its progress callback", "stops at the first progress report after Cancel",
                () =>
                {
                    var cts = new CancellationTokenSource();
                    float last = -1;
                    try { ContinuityMeasure.Measure(big, 65, f => { last = f; if (f > 0.05f) cts.Cancel(); }, cts.Token); }
                    catch (OperationCanceledException) { if (!(last < 0.1f)) throw new InvalidOperationException($"ran on to {last} after Cancel"); return; }
                    throw new InvalidOperationException("not cancelled");
                });

            foreach (double w in new[] { 1e-300, 5e-324, 1e-11, 0.0, -5.0, double.NaN, double.PositiveInfinity })
                yield return HostileCase.Refuse<ArgumentException>("range", $"width {N(w)}", () => new TerrainRange(0.25, 0.25, 0.25 + w, 0.5).Validate(), "range");
            yield return HostileCase.Refuse<ArgumentException>("range", "width 1e-300 named as a width", () => new TerrainRange(0.0, 0.0, 1e-300, 0.5).Validate(), "width", "1E-300", "1E-10");
            yield return HostileCase.Refuse<ArgumentException>("range", "height 1e-12", () => new TerrainRange(0.0, 0.0, 0.5, 1e-12).Validate(), "height", "1E-12", "1E-10");
            yield return HostileCase.Accept("range", "width 1e-9", "above the smallest range drawn (TerrainRange.MinSize = 1e-10); HardCaseTests draws it", () => new TerrainRange(0.25, 0.25, 0.25 + 1e-9, 0.25 + 1e-9).Validate());
            foreach (double c in new[] { -0.1, 1.1, double.NaN, double.NegativeInfinity, 1e308 })
                yield return HostileCase.Refuse<ArgumentException>("range", $"c = {N(c)}", () => new TerrainRange(c, 0, 1, 1).Validate(), "range.c", N(c));
            foreach (double x in new[] { double.NaN })
                yield return HostileCase.Refuse<ArgumentException>("grid", "FindPatch at NaN", () => g.FindPatch(x, 0.5), "x", "NaN");
            yield return HostileCase.Accept("grid", "FindPatch outside the square", "clamped to the border patch, as the shader does", () => g.FindPatch(7.0, -3.0));
            yield return HostileCase.Refuse<ArgumentException>("eval", "16 control points", () => GregoryEval.Evaluate(new Double3[16], 0.5, 0.5, out _, out _, out _), "cp.Length", "16");
            yield return HostileCase.Refuse<ArgumentException>("origin", "an infinite origin", () => RangeOrigin.Snap(new Double2(double.PositiveInfinity, 0)), "origin", "Infinity");
            yield return HostileCase.Refuse<ArgumentOutOfRangeException>("grid", "RegionOf(-1)", () => g.RegionOf(-1), "patch", "-1");
            yield return HostileCase.Refuse<ArgumentOutOfRangeException>("grid", "RegionOf(9)", () => g.RegionOf(9), "patch", "9");
            yield return HostileCase.Refuse<ArgumentException>("pack", "packing a grid with a 1e39 point", () =>
            {
                PatchGrid h = g.Clone();
                h.Patches[2][5] = new Double3(0, 0, 1e39);
                GpuLayout.PackControlPoints(h);
            }, "slot 5", "1E+39");
            yield return HostileCase.Refuse<ArgumentException>("json", "writing a grid with a NaN point", () =>
            {
                PatchGrid h = g.Clone();
                h.Patches[1][7] = new Double3(double.NaN, 0, 0);
                PatchGridJson.Write(h);
            }, "slot 7", "NaN");
        }

        // ---- 4. the fitter's entry: refused before anything is allocated
        static IEnumerable<HostileCase> FitterCases()
        {
            double[] h = HardCaseGrids.Heightmap(17, 1);
            Func<string> state = () => string.Join(",", Array.ConvertAll(h, N));
            foreach (var (c, r) in new[] { (0, 2), (2, 0), (-1, 2), (100000, 100000), (8192, 4096), (2600, 2600), (int.MaxValue, 2) })
                yield return HostileCase.Refuse<ArgumentException>("fitter", $"{c} x {r} patches", () => AllocationFree(() => HeightmapFitter.Fit(h, 17, 17, c, r)),
                    c < 1 ? "columns" : r < 1 ? "rows" : "columns * rows").WithState(state);
            yield return HostileCase.Refuse<ArgumentException>("fitter", "wrong heights length", () => HeightmapFitter.Fit(h, 17, 16, 2, 2), "heights", "289").WithState(state);
            yield return HostileCase.Refuse<ArgumentException>("fitter", "width 1", () => HeightmapFitter.Fit(h, 1, 289, 2, 2), "width", "1").WithState(state);
            yield return HostileCase.Refuse<ArgumentNullException>("fitter", "null heights", () => HeightmapFitter.Fit(null, 17, 17, 2, 2), "heights");
            foreach (double v in new[] { double.NaN, double.PositiveInfinity, double.NegativeInfinity })
            {
                double[] bad = (double[])h.Clone();
                bad[40] = v;
                yield return HostileCase.Refuse<ArgumentException>("fitter", $"height {N(v)} at 40", () => HeightmapFitter.Fit(bad, 17, 17, 2, 2), "40")
                    .WithState(() => string.Join(",", Array.ConvertAll(bad, N)));
            }
        }

        /// <summary>Runs <paramref name="call"/> and fails if it allocated more than 1 MB before throwing (a limit checked after allocating).</summary>
        static void AllocationFree(Action call)
        {
            long before = GC.GetAllocatedBytesForCurrentThread();
            try { call(); }
            finally
            {
                long used = GC.GetAllocatedBytesForCurrentThread() - before;
                if (used > 1 << 20) throw new InvalidOperationException($"allocated {used} bytes before refusing");
            }
        }

        // ---- 5. renderer settings: TerrainParams.CheckSettings, what the renderer and controllers call
        static IEnumerable<HostileCase> SettingsCases()
        {
            TerrainRange r = TerrainRange.full;
            TessellationSettings t = TessellationSettings.Default;
            NoiseSettings n = NoiseSettings.Default;
            var hc = new HeightColorSettings(0.25f, 0.1f, 4f);
            Float3 lo = new Float3(0.2f, 0.3f, 0.1f), hi = new Float3(0.9f, 0.9f, 0.9f);
            HostileCase S(string name, Action call, params string[] mentions) => HostileCase.Refuse<ArgumentException>("settings", name, call, mentions);

            foreach (int tiles in new[] { 0, -1, 1025, int.MaxValue, int.MinValue })
                yield return S($"tiles {tiles}", () => TerrainParams.CheckSettings(r, new TessellationSettings(tiles, 64f, 8f, 0f), n, hc, lo, hi), "tessellation.tiles", tiles.ToString(CultureInfo.InvariantCulture));
            foreach (float f in new[] { 0f, 0.5f, 65f, float.NaN, float.PositiveInfinity, -1f })
                yield return S($"maxFactor {f}", () => TerrainParams.CheckSettings(r, new TessellationSettings(8, f, 8f, 0f), n, hc, lo, hi), "tessellation.maxFactor");
            foreach (float f in new[] { 0f, -1f, float.NaN, float.PositiveInfinity })
                yield return S($"targetPixels {f}", () => TerrainParams.CheckSettings(r, new TessellationSettings(8, 64f, f, 0f), n, hc, lo, hi), "tessellation.targetPixels");
            foreach (float f in new[] { 0.5f, 65f, float.NaN, -2f })
                yield return S($"uniformFactor {f}", () => TerrainParams.CheckSettings(r, new TessellationSettings(8, 64f, 8f, f), n, hc, lo, hi), "tessellation.uniformFactor");
            foreach (float f in new[] { float.NaN, float.PositiveInfinity, float.NegativeInfinity })
                yield return S($"noise amplitude {f}", () => TerrainParams.CheckSettings(r, t, new NoiseSettings(f, 8f, 2f, 2f, 4), hc, lo, hi), "noise.amplitude");
            foreach (float f in new[] { 0f, -1f, float.NaN, 1e30f })
                yield return S($"noise frequency {f}", () => TerrainParams.CheckSettings(r, t, new NoiseSettings(0.01f, f, 2f, 2f, 4), hc, lo, hi), "noise.frequency");
            foreach (float f in new[] { 1f, 0.5f, float.NaN })
                yield return S($"noise alpha {f}", () => TerrainParams.CheckSettings(r, t, new NoiseSettings(0.01f, 8f, f, 2f, 4), hc, lo, hi), "noise.alpha");
            foreach (float f in new[] { 0f, float.NaN, float.NegativeInfinity })
                yield return S($"noise beta {f}", () => TerrainParams.CheckSettings(r, t, new NoiseSettings(0.01f, 8f, 2f, f, 4), hc, lo, hi), "noise.beta");
            foreach (int o in new[] { -1, 1000, int.MinValue })
                yield return S($"noise octaves {o}", () => TerrainParams.CheckSettings(r, t, new NoiseSettings(0.01f, 8f, 2f, 2f, o), hc, lo, hi), "noise.octaves", o.ToString(CultureInfo.InvariantCulture));
            foreach (float f in new[] { 0f, float.NaN })
                yield return S($"gamma {f}", () => TerrainParams.CheckSettings(r, t, n, new HeightColorSettings(f, 0.1f, 4f), lo, hi), "heightColor.gamma");
            yield return S("colour NaN", () => TerrainParams.CheckSettings(r, t, n, hc, new Float3(float.NaN, 0, 0), hi), "colorLow", "NaN");
            yield return S("colour Infinity", () => TerrainParams.CheckSettings(r, t, n, hc, lo, new Float3(0, float.PositiveInfinity, 0)), "colorHigh", "Infinity");
            yield return S("noise vertices -1", () => TerrainParams.CheckSettings(r, t, n, hc, lo, hi, -1f), "noiseVerticesAcross", "-1");
            yield return S("range 1e-13 wide", () => TerrainParams.CheckSettings(new TerrainRange(0.5, 0.5, 0.5 + 1e-13, 0.6), t, n, hc, lo, hi), "range width", "1E-10");
            yield return HostileCase.Accept("settings", "the defaults", "control", () => TerrainParams.CheckSettings(r, t, n, hc, lo, hi));
        }
    }
}
