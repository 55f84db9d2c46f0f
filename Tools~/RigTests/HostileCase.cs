using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Threading.Tasks;
using NUnit.Framework;

namespace GregoryTerrain.Tests
{
    /// <summary>How a hostile case ended (Tools~/development.md, "The hostile-input suite").</summary>
    public enum HostileOutcome { Clear, Unclear, Crash, Hang, AcceptedGarbage, StateChanged, DocumentedAcceptance, RefusedGoodInput }

    /// <summary>
    /// One generated bad (or deliberately odd) input to an entry point, with what must happen: a
    /// refusal of a given exception type whose message names each of <see cref="Mentions"/> (the
    /// field and the value), or a documented acceptance (the call returns; <see cref="Check"/>, when
    /// set, returns text that must name each mention, e.g. a warning). <see cref="State"/>, when set,
    /// snapshots the inputs, compared before and after: a refused call must change nothing.
    /// </summary>
    public sealed class HostileCase
    {
        public string Entry, Name;
        public Action Call;
        public Func<string> Check;
        public Func<string> State;
        public Type Refusal;          // null: a documented acceptance
        public string[] Mentions = new string[0];
        public string Acceptance;     // why accepting is right (troubleshooting.md, "Accepted on purpose")

        /// <summary>Longest message accepted as clear: a user's huge value must be quoted short.</summary>
        public const int MaxMessageLength = 1000;

        public override string ToString() => Entry + ": " + Name;

        public static HostileCase Refuse<T>(string entry, string name, Action call, params string[] mentions) where T : Exception =>
            new HostileCase { Entry = entry, Name = name, Call = call, Refusal = typeof(T), Mentions = mentions };

        public static HostileCase Accept(string entry, string name, string why, Action call, Func<string> check = null, params string[] mentions) =>
            new HostileCase { Entry = entry, Name = name, Call = call, Acceptance = why, Check = check, Mentions = mentions };

        public HostileCase WithState(Func<string> state) { State = state; return this; }

        /// <summary>Runs the case on a worker with a watchdog; <paramref name="detail"/> says what happened.</summary>
        public HostileOutcome Run(int timeoutMs, out string detail, out double seconds)
        {
            string before = State?.Invoke();
            Exception thrown = null;
            string checkText = null;
            var watch = Stopwatch.StartNew();
            var task = Task.Run(() =>
            {
                try { Call(); if (Check != null) checkText = Check(); }
                catch (Exception e) { thrown = e; }
            });
            bool finished = task.Wait(timeoutMs);
            seconds = watch.Elapsed.TotalSeconds;
            if (!finished) { detail = $"no answer within {timeoutMs} ms"; return HostileOutcome.Hang; }
            string after = State?.Invoke();
            if (Refusal == null)
            {
                if (thrown != null) { detail = $"{thrown.GetType().Name}: {Short(thrown.Message)}"; return HostileOutcome.RefusedGoodInput; }
                foreach (string m in Mentions)
                    if (checkText == null || !checkText.Contains(m)) { detail = $"accepted, but the report does not name '{m}': {Short(checkText)}"; return HostileOutcome.Unclear; }
                detail = "accepted: " + Acceptance + (checkText != null ? " -> " + Short(checkText) : "");
                return HostileOutcome.DocumentedAcceptance;
            }
            if (thrown == null) { detail = "accepted without a word"; return HostileOutcome.AcceptedGarbage; }
            detail = $"{thrown.GetType().Name}: {Short(thrown.Message)}";
            if (!Refusal.IsInstanceOfType(thrown)) return HostileOutcome.Crash;
            if (before != after) { detail += " (and the input changed)"; return HostileOutcome.StateChanged; }
            if (thrown.Message.Length > MaxMessageLength) { detail = $"message of {thrown.Message.Length} characters: {Short(thrown.Message)}"; return HostileOutcome.Unclear; }
            foreach (string m in Mentions)
                if (!thrown.Message.Contains(m)) { detail += $" (does not name '{m}')"; return HostileOutcome.Unclear; }
            return HostileOutcome.Clear;
        }

        static string Short(string s) => s == null ? "null" : s.Length <= 300 ? s : s.Substring(0, 300) + "...";
    }

    /// <summary>Counts of a suite's outcomes and its longest case, printed at the end of a fixture.</summary>
    public sealed class HostileTally
    {
        readonly Dictionary<HostileOutcome, int> _counts = new Dictionary<HostileOutcome, int>();
        double _longest;
        string _longestName;

        public void Add(HostileCase c, HostileOutcome o, double seconds)
        {
            lock (_counts)
            {
                _counts.TryGetValue(o, out int n);
                _counts[o] = n + 1;
                if (seconds > _longest) { _longest = seconds; _longestName = c.ToString(); }
            }
        }

        public override string ToString()
        {
            var parts = new List<string>();
            foreach (HostileOutcome o in Enum.GetValues(typeof(HostileOutcome)))
            {
                _counts.TryGetValue(o, out int n);
                parts.Add($"{o} {n}");
            }
            return string.Join(", ", parts) + $"; longest case {_longest:F3} s ({_longestName})";
        }

        /// <summary>Runs the case, tallies it and fails unless it ended clear or as a documented acceptance.</summary>
        public void Assert(HostileCase c, int timeoutMs)
        {
            HostileOutcome o = c.Run(timeoutMs, out string detail, out double seconds);
            Add(c, o, seconds);
            TestContext.Out.WriteLine($"{o} in {seconds:F3} s: {detail}");
            NUnit.Framework.Assert.That(o == HostileOutcome.Clear || o == HostileOutcome.DocumentedAcceptance, Is.True, $"{c}: {o}: {detail}");
        }
    }
}
