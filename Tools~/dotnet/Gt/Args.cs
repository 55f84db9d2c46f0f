using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;

namespace GregoryTerrain.Rig
{
    /// <summary>A mistake in the command line itself (unknown or repeated option, malformed or out-of-range number): exit code 2.</summary>
    sealed class UsageException : ArgumentException
    {
        public UsageException(string message) : base(message) { }
    }

    /// <summary>
    /// The values one number of an option accepts: finite, in [Min, Max] (above Min when MinOpen),
    /// written as an integer ("12", not "1.2e1") when Whole, not 0 when NotZero. Label names the number inside a comma-separated option.
    /// </summary>
    sealed class Bounds
    {
        public string Label;
        public bool Whole, MinOpen, NotZero;
        public double Min, Max;

        public static Bounds Int(long min, long max, string label = null) => new Bounds { Label = label, Whole = true, Min = min, Max = max };
        public static Bounds Real(double min, double max, string label = null) => new Bounds { Label = label, Min = min, Max = max };
        /// <summary>(min, max]: a size, a rate or a pixel error that must be more than <paramref name="min"/>.</summary>
        public static Bounds Above(double min, double max, string label = null) => new Bounds { Label = label, Min = min, Max = max, MinOpen = true };

        public bool Holds(double v) => (MinOpen ? v > Min : v >= Min) && v <= Max && !(NotZero && v == 0);

        /// <summary>As the messages print it: "1..64", "&gt;0..16384", "-1000..1000, not 0".</summary>
        public string Text => (MinOpen ? ">" : "") + N(Min) + ".." + N(Max) + (NotZero ? ", not 0" : "");

        static string N(double v) => v.ToString("G", CultureInfo.InvariantCulture);

        /// <summary>The number in <paramref name="text"/>, or a UsageException naming <paramref name="where"/>, the text and this range.</summary>
        public double Parse(string where, string text)
        {
            string q = InputLimits.Quote(text);
            if (text.Length == 0) throw new UsageException($"{where} needs a value ({Text})");
            if (!double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out double v))
                throw new UsageException($"{where} {q} is not a number ({Text})");
            if (double.IsNaN(v) || double.IsInfinity(v))
                throw new UsageException($"{where} {q} is not a finite number ({Text})");
            if (!Holds(v))
                throw new UsageException($"{where} {q} is out of range ({Text})");
            if (Whole && !long.TryParse(text, NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out _))
                throw new UsageException($"{where} {q} is not an integer ({Text})");
            return v;
        }
    }

    /// <summary>
    /// A numeric option of a command (Program.Register declares each with its range): one number,
    /// a fixed count of labelled comma-separated numbers, or (List) one or more of Parts[0].
    /// </summary>
    sealed class NumericOption
    {
        public string Name;
        public Bounds[] Parts;
        public bool List;

        /// <summary>Most numbers a list option takes: each is a run of its own, so more is a typo.</summary>
        public const int MaxListCount = 64;

        public static NumericOption Int(string name, long min, long max) => One(name, Bounds.Int(min, max));
        public static NumericOption Real(string name, double min, double max) => One(name, Bounds.Real(min, max));
        public static NumericOption Above(string name, double min, double max) => One(name, Bounds.Above(min, max));
        public static NumericOption One(string name, Bounds b) => new NumericOption { Name = name, Parts = new[] { b } };
        public static NumericOption Numbers(string name, params Bounds[] parts) => new NumericOption { Name = name, Parts = parts };
        public static NumericOption ListOf(string name, Bounds each) => new NumericOption { Name = name, Parts = new[] { each }, List = true };

        /// <summary>"N (1..64)", "F,DEGREES (frames 1..100000, degrees -90..90)", "N,... (1..64)": for help and messages.</summary>
        public string Text => Parts.Length == 1
            ? (List ? "N,... (" : "N (") + Parts[0].Text + ")"
            : string.Join(",", Parts.Select(p => p.Label)) + " (" + string.Join(", ", Parts.Select(p => p.Label + " " + p.Text)) + ")";

        /// <summary>Every number of <paramref name="value"/>, each checked; a UsageException names the option, the value and the range.</summary>
        public double[] Parse(string value)
        {
            string where = "--" + Name;
            if (Parts.Length == 1 && !List) return new[] { Parts[0].Parse(where, value) };
            string whole = InputLimits.Quote(value);
            if (value.Length == 0) throw new UsageException($"{where} needs a value: {Text}");
            string[] items = value.Split(',');
            if (List ? items.Length > MaxListCount : items.Length != Parts.Length)
                throw new UsageException(List
                    ? $"{where} {whole} has {items.Length} numbers (at most {MaxListCount})"
                    : $"{where} {whole} needs {Parts.Length} comma-separated numbers, got {items.Length}: {Text}");
            var r = new double[items.Length];
            for (int i = 0; i < items.Length; i++)
            {
                Bounds b = List ? Parts[0] : Parts[i];
                r[i] = b.Parse(b.Label == null ? $"{where} {whole}:" : $"{where} {whole}: {b.Label}", items[i]);
            }
            return r;
        }
    }

    /// <summary>
    /// Minimal "--name value" / "--flag" parser with errors that name the option and value. Only the
    /// options the command declares are accepted (a mistyped one is refused, not ignored); a numeric
    /// option is parsed and range-checked here, before the command runs (NumericOption). Values are
    /// quoted short in messages (InputLimits.Quote).
    /// </summary>
    sealed class Args
    {
        readonly Dictionary<string, string> _values = new Dictionary<string, string>(StringComparer.Ordinal);
        readonly Dictionary<string, double[]> _numbers = new Dictionary<string, double[]>(StringComparer.Ordinal);
        readonly IReadOnlyDictionary<string, NumericOption> _numeric;

        /// <param name="known">The options this command reads; null accepts any.</param>
        /// <param name="numeric">Its numeric options with their ranges; each one given is checked now.</param>
        public Args(string[] argv, int start, ICollection<string> known = null, IReadOnlyDictionary<string, NumericOption> numeric = null)
        {
            _numeric = numeric ?? new Dictionary<string, NumericOption>();
            for (int i = start; i < argv.Length; i++)
            {
                string a = argv[i];
                if (!a.StartsWith("--", StringComparison.Ordinal) || a.Length == 2)
                    throw new UsageException($"unexpected argument '{InputLimits.Quote(a)}' (options are --name value)");
                string name = a.Substring(2);
                if (known != null && !known.Contains(name) && !_numeric.ContainsKey(name))
                    throw new UsageException($"unknown option --{InputLimits.Quote(name)} (this command takes {Names(known, _numeric.Keys)})");
                if (_values.ContainsKey(name))
                    throw new UsageException($"--{name} is given twice");
                bool hasValue = i + 1 < argv.Length && !(argv[i + 1].StartsWith("--", StringComparison.Ordinal));
                _values[name] = hasValue ? argv[++i] : "";
                if (_numeric.TryGetValue(name, out NumericOption n)) _numbers[name] = n.Parse(_values[name]);
            }
        }

        static string Names(IEnumerable<string> known, IEnumerable<string> numeric)
        {
            var list = new List<string>((known ?? new string[0]).Concat(numeric));
            list.Sort(StringComparer.Ordinal);
            return list.Count == 0 ? "no options" : "--" + string.Join(", --", list);
        }

        public bool Flag(string name) => _values.ContainsKey(name);

        public string String(string name, string fallback = null)
        {
            if (_values.TryGetValue(name, out var v))
                return v.Length > 0 ? v : throw new UsageException($"--{name} needs a value");
            if (fallback != null) return fallback;
            throw new UsageException($"--{name} is required");
        }

        public double Double(string name, double? fallback = null) => Read(name, 1, fallback.HasValue ? new[] { fallback.Value } : null)[0];

        public int Int(string name, int? fallback = null)
        {
            double v = Double(name, fallback);
            if (!_numeric[name].Parts[0].Whole) throw new InvalidOperationException($"--{name} is read as an integer but declared as a real number (Program.Register)");
            return (int)v;
        }

        /// <summary>A comma-separated option of <paramref name="count"/> numbers (0: a list of any length); <paramref name="fallback"/> is the command's own default text.</summary>
        public double[] Doubles(string name, int count, string fallback = null) =>
            Read(name, count, fallback?.Split(',').Select(s => double.Parse(s, CultureInfo.InvariantCulture)).ToArray());

        public int[] Ints(string name, string fallback)
        {
            double[] v = Doubles(name, 0, fallback);
            if (!_numeric[name].Parts[0].Whole) throw new InvalidOperationException($"--{name} is read as integers but declared as real numbers (Program.Register)");
            return Array.ConvertAll(v, x => (int)x);
        }

        double[] Read(string name, int count, double[] fallback)
        {
            if (!_numeric.TryGetValue(name, out NumericOption n) || (count > 0 && !n.List && n.Parts.Length != count) || (count == 0 && !n.List))
                throw new InvalidOperationException($"--{name} is read as {(count == 0 ? "a list of numbers" : count + " number(s)")} but not declared so with a range (Program.Register)");
            if (_numbers.TryGetValue(name, out double[] v)) return v;
            if (fallback != null) return fallback;
            throw new UsageException($"--{name} is required: {n.Text}");
        }
    }
}
