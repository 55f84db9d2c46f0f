using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Text;

namespace GregoryTerrain
{
    /// <summary>
    /// Versioned JSON for a patch grid, written and read by hand (Core has no dependencies):
    /// <c>{"format":"gregory-terrain-grid","version":1,"columns":n,"rows":m,"xLines":[..n+1],
    /// "yLines":[..m+1],"patches":[[[x,y,z] x 20] x n*m]}</c>, patches in index order j * n + i.
    /// Doubles are written in the shortest form that parses back to the same bits (checked, with
    /// G17 as the fallback; -0 kept), invariant culture, so <c>Read(Write(g))</c> equals g bit for bit.
    /// Reading throws FormatException naming the field and the line/column for any bad file
    /// (malformed or truncated JSON, wrong format or version, wrong counts, missing fields, non-finite
    /// numbers, a grid that fails <see cref="PatchGrid.Validate"/>).
    /// </summary>
    internal static class PatchGridJson
    {
        public const string FormatName = "gregory-terrain-grid";
        public const int Version = 1;

        /// <summary>The grid as JSON text. Throws ArgumentException if the grid is not valid.</summary>
        public static string Write(PatchGrid grid)
        {
            if (grid == null) throw new ArgumentNullException(nameof(grid));
            grid.Validate();
            var sb = new StringBuilder();
            sb.Append("{\"format\":\"").Append(FormatName).Append("\",\"version\":").Append(Version.ToString(CultureInfo.InvariantCulture));
            sb.Append(",\"columns\":").Append(grid.Columns.ToString(CultureInfo.InvariantCulture));
            sb.Append(",\"rows\":").Append(grid.Rows.ToString(CultureInfo.InvariantCulture));
            sb.Append(",\n\"xLines\":");
            WriteArray(sb, grid.XLines);
            sb.Append(",\n\"yLines\":");
            WriteArray(sb, grid.YLines);
            sb.Append(",\n\"patches\":[");
            for (int p = 0; p < grid.PatchCount; p++)
            {
                sb.Append(p == 0 ? "\n[" : ",\n[");
                for (int k = 0; k < GregoryPatch.SlotCount; k++)
                {
                    Double3 c = grid.Patches[p][k];
                    if (k > 0) sb.Append(',');
                    sb.Append('[').Append(Number(c.x)).Append(',').Append(Number(c.y)).Append(',').Append(Number(c.z)).Append(']');
                }
                sb.Append(']');
            }
            sb.Append("]}\n");
            return sb.ToString();
        }

        static void WriteArray(StringBuilder sb, double[] values)
        {
            sb.Append('[');
            for (int k = 0; k < values.Length; k++)
            {
                if (k > 0) sb.Append(',');
                sb.Append(Number(values[k]));
            }
            sb.Append(']');
        }

        /// <summary>Round-trip text of a finite double ("R", verified; G17 if a runtime's "R" does not round-trip).</summary>
        public static string Number(double d)
        {
            if (d == 0) return BitConverter.DoubleToInt64Bits(d) < 0 ? "-0.0" : "0";
            string s = d.ToString("R", CultureInfo.InvariantCulture);
            if (BitConverter.DoubleToInt64Bits(double.Parse(s, NumberStyles.Float, CultureInfo.InvariantCulture)) != BitConverter.DoubleToInt64Bits(d))
                s = d.ToString("G17", CultureInfo.InvariantCulture);
            return s;
        }

        /// <summary>Parses a grid written by <see cref="Write"/>. Throws FormatException on any bad input.</summary>
        public static PatchGrid Read(string json)
        {
            if (json == null) throw new ArgumentNullException(nameof(json));
            using (var reader = new StringReader(json)) return Read(reader);
        }

        /// <summary>
        /// Reads a grid file: refuses a folder, a missing file or one over
        /// <see cref="InputLimits.MaxJsonBytes"/> before reading, then streams it (<see cref="Read(TextReader)"/>).
        /// Throws IOException for the file, FormatException for its contents.
        /// </summary>
        public static PatchGrid ReadFile(string path)
        {
            InputLimits.CheckFileToRead(path, InputLimits.MaxJsonBytes);
            using (var reader = new StreamReader(path, Encoding.UTF8, true, 1 << 16)) return Read(reader);
        }

        /// <summary>
        /// Streams a grid from <paramref name="reader"/>: numbers go straight into the control points,
        /// with no tree in between, so memory is the grid plus a fixed buffer. Members may come in
        /// any order; each must appear once, and unknown members are refused (a misspelt name is
        /// named, not ignored). Throws FormatException naming the field, the value (quoted short) and
        /// the line/column.
        /// </summary>
        public static PatchGrid Read(TextReader reader)
        {
            if (reader == null) throw new ArgumentNullException(nameof(reader));
            var r = new JsonReader(reader);
            if (r.Peek() != JsonKind.Object) throw Fail(r, "the document", "expected an object");
            r.Expect('{');
            var seen = new HashSet<string>(StringComparer.Ordinal);
            int n = 0, m = 0;
            double[] xl = null, yl = null;
            List<GregoryPatch> patches = null;
            long patchesLine = 0, patchesColumn = 0;
            if (!r.TryClose('}'))
                do
                {
                    r.Peek();
                    long line = r.Line, column = r.Column;
                    string name = r.ReadString(InputLimits.QuotedLength + 1, out long nameLength);
                    if (Array.IndexOf(Members, name) < 0 || nameLength != name.Length)
                        throw Fail(line, column, $"member \"{InputLimits.Quote(name, nameLength)}\"", $"is not part of the format (expected {string.Join(", ", Members)})");
                    if (!seen.Add(name)) throw Fail(line, column, name, "appears twice (each member must appear once)");
                    r.Expect(':');
                    switch (name)
                    {
                        case "format":
                            Kind(r, name, JsonKind.String);
                            long fl = r.Line, fc = r.Column;
                            string format = r.ReadString(InputLimits.QuotedLength + 1, out long formatLength);
                            if (format != FormatName || formatLength != format.Length)
                                throw Fail(fl, fc, "format", $"is \"{InputLimits.Quote(format, formatLength)}\", expected \"{FormatName}\"");
                            break;
                        case "version":
                            long vl = r.Line, vc = r.Column;
                            int version = ReadInt(r, name, out string vt);
                            if (version != Version) throw Fail(vl, vc, "version", $"is {vt}, this reader knows version {Version} only");
                            break;
                        case "columns": n = ReadCount(r, name); break;
                        case "rows": m = ReadCount(r, name); break;
                        case "xLines": xl = ReadLines(r, name); break;
                        case "yLines": yl = ReadLines(r, name); break;
                        case "patches":
                            r.Peek();
                            patchesLine = r.Line; patchesColumn = r.Column;
                            patches = ReadPatches(r, n);
                            break;
                    }
                } while (r.Continues('}'));
            r.ExpectEnd();

            foreach (string name in Members)
                if (!seen.Contains(name)) throw Fail(r, name, "is missing");
            CheckGridSize(r, n, m);
            if (xl.Length != n + 1) throw Fail(r, "xLines", $"has {xl.Length} numbers, need columns + 1 = {n + 1}");
            if (yl.Length != m + 1) throw Fail(r, "yLines", $"has {yl.Length} numbers, need rows + 1 = {m + 1}");
            if (patches.Count != n * m)
                throw Fail(patchesLine, patchesColumn, "patches", $"has {patches.Count} patches, columns * rows = {n * m}");
            var grid = new PatchGrid(n, m, xl, yl, patches.ToArray());
            try
            {
                grid.Validate();
            }
            catch (ArgumentException ex)
            {
                throw new FormatException("PatchGridJson: the grid in the file is not valid: " + ex.Message, ex);
            }
            return grid;
        }

        static readonly string[] Members = { "format", "version", "columns", "rows", "xLines", "yLines", "patches" };

        static void CheckGridSize(JsonReader r, int n, int m)
        {
            try { GpuLayout.CheckSize(n, m); }
            catch (ArgumentException ex) { throw Fail(r, "columns * rows", ex.Message); }
        }

        /// <summary>A number, with a syntax error inside it blamed on <paramref name="path"/>.</summary>
        static double Number(JsonReader r, FieldPath path)
        {
            try { return r.ReadNumber(); }
            catch (FormatException e) { throw new FormatException($"PatchGridJson: {path}: {e.Message}", e); }
        }

        static void Kind(JsonReader r, FieldPath path, JsonKind kind)
        {
            JsonKind k = r.Peek();
            if (k == JsonKind.End) throw Fail(r, path, "is missing its value (the file is truncated)");
            if (k == JsonKind.Invalid) throw Fail(r, path, "is not a JSON value (JSON has no NaN or Infinity)");
            if (k != kind) throw Fail(r, path, $"is a {Name(k)}, expected a {Name(kind)}");
        }

        static string Name(JsonKind k) => k == JsonKind.True || k == JsonKind.False ? "boolean" : k.ToString().ToLowerInvariant();

        static int ReadCount(JsonReader r, string path)
        {
            long line = r.Line, column = r.Column;
            int v = ReadInt(r, path, out string text);
            if (v < 1) throw Fail(line, column, path, $"is {text}, need at least 1");
            return v;
        }

        static int ReadInt(JsonReader r, string path, out string text)
        {
            Kind(r, path, JsonKind.Number);
            long line = r.Line, column = r.Column;
            double d = Number(r, path);
            text = r.NumberText;
            if (d != Math.Floor(d) || d < int.MinValue || d > int.MaxValue)
                throw Fail(line, column, path, $"is {InputLimits.Quote(text)}, expected an integer in [{int.MinValue}, {int.MaxValue}]");
            return (int)d;
        }

        static double ReadDouble(JsonReader r, FieldPath path)
        {
            Kind(r, path, JsonKind.Number);
            long line = r.Line, column = r.Column;
            double d = Number(r, path);
            if (!GMath.isfinite(d)) throw Fail(line, column, path, $"is {InputLimits.Quote(r.NumberText)}, which is not a finite double");
            return d;
        }

        /// <summary>Grid lines: at most the GPU's patch limit + 1 of them, refused as soon as the array passes it.</summary>
        static double[] ReadLines(JsonReader r, string path)
        {
            Kind(r, path, JsonKind.Array);
            r.Expect('[');
            var values = new List<double>();
            if (!r.TryClose(']'))
                do
                {
                    if (values.Count > GpuLayout.MaxPatches)
                        throw Fail(r, path, $"has more than {GpuLayout.MaxPatches + 1} numbers (the GPU's limit of {GpuLayout.MaxPatches} patches + 1)");
                    values.Add(ReadDouble(r, new FieldPath(path, 0, values.Count)));
                } while (r.Continues(']'));
            return values.ToArray();
        }

        /// <summary>
        /// The patches, each built as it is read. The list grows with the file, never with a count the
        /// file claims, and stops at the GPU's limit, so a small file cannot make it allocate much.
        /// </summary>
        static List<GregoryPatch> ReadPatches(JsonReader r, int columns)
        {
            Kind(r, "patches", JsonKind.Array);
            r.Expect('[');
            var patches = new List<GregoryPatch>();
            long limit = GpuLayout.MaxBufferBytes / GpuLayout.ControlPointBytes(1);
            if (r.TryClose(']')) return patches;
            var c = new double[3];
            do
            {
                int p = patches.Count;
                var path = new FieldPath("patches", columns, p);
                if (p >= limit) throw Fail(r, "patches", $"has more than {limit} patches, the most the GPU buffers hold");
                Kind(r, path, JsonKind.Array);
                r.Expect('[');
                var patch = new GregoryPatch();
                int k = 0;
                if (!r.TryClose(']'))
                    do
                    {
                        if (k >= GregoryPatch.SlotCount) throw Fail(r, path, $"has more than {GregoryPatch.SlotCount} points");
                        ReadPoint(r, path.Child(k), c);
                        patch[k++] = new Double3(c[0], c[1], c[2]);
                    } while (r.Continues(']'));
                if (k != GregoryPatch.SlotCount) throw Fail(r, path, $"has {k} points, need {GregoryPatch.SlotCount}");
                patches.Add(patch);
            } while (r.Continues(']'));
            return patches;
        }

        static void ReadPoint(JsonReader r, FieldPath path, double[] c)
        {
            Kind(r, path, JsonKind.Array);
            r.Expect('[');
            int k = 0;
            if (!r.TryClose(']'))
                do
                {
                    if (k >= 3) throw Fail(r, path, "has more than 3 numbers, need x, y, z");
                    c[k] = ReadDouble(r, path.Child(k));
                    k++;
                } while (r.Continues(']'));
            if (k != 3) throw Fail(r, path, $"has {k} numbers, need 3");
        }

        static FormatException Fail(JsonReader r, FieldPath path, string what) => Fail(r.Line, r.Column, path, what);

        static FormatException Fail(long line, long column, FieldPath path, string what) =>
            new FormatException(string.Format(CultureInfo.InvariantCulture, "PatchGridJson: {0} {1} (line {2}, column {3}).", path, what, line, column));
    }

    /// <summary>
    /// Where a value sits in a grid file, for messages: "xLines[3]" or "patches[7] (patch (1, 2))[5][2]".
    /// A value type formatted only when a message needs it, so reading costs no string per number.
    /// </summary>
    internal readonly struct FieldPath
    {
        readonly string _name;
        readonly int _columns, _index, _point, _coord;

        public FieldPath(string name, int columns, int index, int point = -1, int coord = -1)
        {
            _name = name; _columns = columns; _index = index; _point = point; _coord = coord;
        }

        public static implicit operator FieldPath(string name) => new FieldPath(name, 0, -1);

        /// <summary>The path one level down (the next index).</summary>
        public FieldPath Child(int k) => _point < 0 ? new FieldPath(_name, _columns, _index, k) : new FieldPath(_name, _columns, _index, _point, k);

        public override string ToString()
        {
            var sb = new StringBuilder(_name);
            if (_index >= 0) sb.Append('[').Append(_index.ToString(CultureInfo.InvariantCulture)).Append(']');
            if (_index >= 0 && _columns > 0)
                sb.Append(string.Format(CultureInfo.InvariantCulture, " (patch ({0}, {1}))", _index % _columns, _index / _columns));
            if (_point >= 0) sb.Append('[').Append(_point.ToString(CultureInfo.InvariantCulture)).Append(']');
            if (_coord >= 0) sb.Append('[').Append(_coord.ToString(CultureInfo.InvariantCulture)).Append(']');
            return sb.ToString();
        }
    }
}
