using System;
using System.Collections.Generic;
using System.Globalization;

namespace GregoryTerrain.Rig
{
    /// <summary>A mistake in the command line itself (unknown or repeated option, malformed number): exit code 2.</summary>
    sealed class UsageException : ArgumentException
    {
        public UsageException(string message) : base(message) { }
    }

    /// <summary>
    /// Minimal "--name value" / "--flag" parser with errors that name the option and value. Only the
    /// options the command declares are accepted (a mistyped one is refused, not ignored); numbers
    /// must be finite. Values are quoted short in messages (InputLimits.Quote).
    /// </summary>
    sealed class Args
    {
        readonly Dictionary<string, string> _values = new Dictionary<string, string>(StringComparer.Ordinal);

        /// <param name="known">The options this command reads; null accepts any (internal use).</param>
        public Args(string[] argv, int start, ICollection<string> known = null)
        {
            for (int i = start; i < argv.Length; i++)
            {
                string a = argv[i];
                if (!a.StartsWith("--", StringComparison.Ordinal) || a.Length == 2)
                    throw new UsageException($"unexpected argument '{InputLimits.Quote(a)}' (options are --name value)");
                string name = a.Substring(2);
                if (known != null && !known.Contains(name))
                    throw new UsageException($"unknown option --{InputLimits.Quote(name)} (this command takes {Names(known)})");
                if (_values.ContainsKey(name))
                    throw new UsageException($"--{name} is given twice");
                bool hasValue = i + 1 < argv.Length && !(argv[i + 1].StartsWith("--", StringComparison.Ordinal));
                _values[name] = hasValue ? argv[++i] : "";
            }
        }

        static string Names(ICollection<string> known)
        {
            var list = new List<string>(known);
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

        public double Double(string name, double? fallback = null)
        {
            string s = String(name, fallback?.ToString("R", CultureInfo.InvariantCulture));
            return Number(name, s, s);
        }

        public int Int(string name, int? fallback = null)
        {
            string s = String(name, fallback?.ToString(CultureInfo.InvariantCulture));
            if (!int.TryParse(s, NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out int v))
                throw new UsageException($"--{name} '{InputLimits.Quote(s)}' is not an integer in [{int.MinValue}, {int.MaxValue}]");
            return v;
        }

        public double[] Doubles(string name, int count, string fallback = null)
        {
            string s = String(name, fallback);
            var parts = s.Split(',');
            if (parts.Length != count)
                throw new UsageException($"--{name} '{InputLimits.Quote(s)}' needs {count} comma-separated numbers, got {parts.Length}");
            var r = new double[count];
            for (int i = 0; i < count; i++) r[i] = Number(name, s, parts[i]);
            return r;
        }

        /// <summary>A finite double, or a UsageException naming the option, its value and the bad part.</summary>
        public static double Number(string name, string whole, string part)
        {
            string where = ReferenceEquals(whole, part) ? $"--{name} '{InputLimits.Quote(whole)}'" : $"--{name} '{InputLimits.Quote(whole)}': '{InputLimits.Quote(part)}'";
            if (!double.TryParse(part, NumberStyles.Float, CultureInfo.InvariantCulture, out double v))
                throw new UsageException($"{where} is not a number");
            if (double.IsNaN(v) || double.IsInfinity(v))
                throw new UsageException($"{where} is not a finite number (limit: |value| <= {double.MaxValue:R})");
            return v;
        }
    }
}
