using System;
using System.Collections.Generic;
using System.Globalization;
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
    public static class PatchGridJson
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
            JsonValue root = new JsonReader(json).ReadDocument();
            if (root.Kind != JsonKind.Object) throw Fail(root, "the document", "expected an object");

            JsonValue format = Field(root, "format", JsonKind.String);
            if (format.Text != FormatName)
                throw Fail(format, "format", $"is \"{format.Text}\", expected \"{FormatName}\"");
            JsonValue version = Field(root, "version", JsonKind.Number);
            if (ToInt(version, "version") != Version)
                throw Fail(version, "version", $"is {version.Text}, this reader knows version {Version} only");
            int n = ToInt(Field(root, "columns", JsonKind.Number), "columns");
            int m = ToInt(Field(root, "rows", JsonKind.Number), "rows");
            if (n < 1) throw Fail(root.Get("columns"), "columns", $"is {n}, need at least 1");
            if (m < 1) throw Fail(root.Get("rows"), "rows", $"is {m}, need at least 1");
            if ((long)n * m > int.MaxValue) throw Fail(root, "columns * rows", $"{(long)n * m} is too many patches");

            double[] xl = Numbers(Field(root, "xLines", JsonKind.Array), "xLines", n + 1);
            double[] yl = Numbers(Field(root, "yLines", JsonKind.Array), "yLines", m + 1);
            JsonValue pa = Field(root, "patches", JsonKind.Array);
            if (pa.Items.Count != n * m)
                throw Fail(pa, "patches", $"has {pa.Items.Count} patches, columns * rows = {n * m}");
            var patches = new GregoryPatch[n * m];
            for (int p = 0; p < patches.Length; p++)
            {
                string path = $"patches[{p}] (patch ({p % n}, {p / n}))";
                JsonValue pv = pa.Items[p];
                if (pv.Kind != JsonKind.Array) throw Fail(pv, path, "expected an array of 20 points");
                if (pv.Items.Count != GregoryPatch.SlotCount) throw Fail(pv, path, $"has {pv.Items.Count} points, need {GregoryPatch.SlotCount}");
                var patch = new GregoryPatch();
                for (int k = 0; k < GregoryPatch.SlotCount; k++)
                {
                    double[] c = Numbers(pv.Items[k], $"{path}[{k}]", 3);
                    patch[k] = new Double3(c[0], c[1], c[2]);
                }
                patches[p] = patch;
            }
            var grid = new PatchGrid(n, m, xl, yl, patches);
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

        static JsonValue Field(JsonValue obj, string name, JsonKind kind)
        {
            JsonValue v = obj.Get(name);
            if (v == null) throw Fail(obj, name, "is missing");
            if (v.Kind != kind) throw Fail(v, name, $"is a {v.Kind.ToString().ToLowerInvariant()}, expected a {kind.ToString().ToLowerInvariant()}");
            return v;
        }

        static int ToInt(JsonValue v, string path)
        {
            double d = ToDouble(v, path);
            if (d != Math.Floor(d) || d < int.MinValue || d > int.MaxValue) throw Fail(v, path, $"is {v.Text}, expected an integer");
            return (int)d;
        }

        static double ToDouble(JsonValue v, string path)
        {
            if (v.Kind != JsonKind.Number) throw Fail(v, path, $"is a {v.Kind.ToString().ToLowerInvariant()}, expected a number");
            double d = double.Parse(v.Text, NumberStyles.Float, CultureInfo.InvariantCulture);
            if (!GMath.isfinite(d)) throw Fail(v, path, $"is {v.Text}, which is not a finite double");
            return d;
        }

        static double[] Numbers(JsonValue v, string path, int count)
        {
            if (v.Kind != JsonKind.Array) throw Fail(v, path, "expected an array");
            if (v.Items.Count != count) throw Fail(v, path, $"has {v.Items.Count} numbers, need {count}");
            var r = new double[count];
            for (int k = 0; k < count; k++) r[k] = ToDouble(v.Items[k], $"{path}[{k}]");
            return r;
        }

        internal static FormatException Fail(JsonValue at, string path, string what) =>
            new FormatException($"PatchGridJson: {path} {what} (line {at.Line}, column {at.Column}).");
    }
}
