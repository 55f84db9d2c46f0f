using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;

namespace GregoryTerrain.Rig.Tests
{
    /// <summary>
    /// Static checks over the renderer's C# (Runtime/GregoryTerrainRenderer*.cs) for state that only a
    /// Unity editor could show going wrong: what the property block is known to hold once it is
    /// cleared, the draw's bounds against the shader's tile culling, what the draw mode is cached
    /// against, the device check before any structured buffer, and the range origin per camera.
    /// The Unity-side tests (Tests/Runtime) check the same in Unity; each check here is also run on
    /// the broken code it replaces, which it must reject.
    /// </summary>
    [TestFixture]
    public class RendererStateSourceTests
    {
        static string StripComments(string code) =>
            Regex.Replace(code, @"//[^\n]*|/\*.*?\*/", "", RegexOptions.Singleline);

        static string RendererCode() => string.Join("\n",
            Directory.GetFiles(PackageRoot.Combine("Runtime"), "GregoryTerrainRenderer*.cs").OrderBy(f => f)
                .Select(f => StripComments(File.ReadAllText(f))));

        /// <summary>The body (braces included) of the method or property declared as <paramref name="name"/>, or null.</summary>
        internal static string Body(string code, string name)
        {
            Match m = Regex.Match(code, $@"\b{Regex.Escape(name)}\s*(\([^)]*\))?\s*(?=\{{)");
            if (!m.Success) return null;
            int start = m.Index + m.Length, depth = 0;
            for (int i = start; i < code.Length; i++)
            {
                if (code[i] == '{') depth++;
                else if (code[i] == '}' && --depth == 0) return code.Substring(start, i - start + 1);
            }
            return null;
        }

        /// <summary>The name of the method whose body holds <paramref name="index"/>.</summary>
        static string EnclosingMethod(string code, int index)
        {
            foreach (Match m in Regex.Matches(code.Substring(0, index), @"\b(\w+)\s*\([^)]*\)\s*\{").Cast<Match>().Reverse())
            {
                string body = Body(code.Substring(m.Index), m.Groups[1].Value);
                if (body != null && m.Index + m.Length - 1 + body.Length > index) return m.Groups[1].Value;
            }
            return null;
        }

        // ---- 1. What the property block holds, forgotten with it ----------------------------------

        /// <summary>
        /// Memos of what the property block holds (fields named <c>_sent*</c> / <c>_bound*</c>) that
        /// the one method clearing the block does not reset: after the clear each would skip sending
        /// a value the block no longer has. Also a problem: the block cleared in more than one place.
        /// </summary>
        internal static List<string> MemosNotResetWithTheBlock(string code)
        {
            var problems = new List<string>();
            var clears = Regex.Matches(code, @"_props\s*\??\s*\.\s*Clear\s*\(\s*\)");
            if (clears.Count != 1) { problems.Add($"the property block is cleared in {clears.Count} places, not one"); if (clears.Count == 0) return problems; }
            string method = EnclosingMethod(code, clears[0].Index);
            string body = Body(code, method) ?? "";
            var memos = Regex.Matches(code, @"(?<![\w.])(_(?:sent|bound)\w*)").Select(m => m.Groups[1].Value).Distinct();
            foreach (string memo in memos)
                if (!Regex.IsMatch(body, $@"\b{memo}\s*=(?!=)"))
                    problems.Add($"{memo} is not reset in {method}, which clears the property block");
            return problems;
        }

        [Test]
        public void EveryMemoOfThePropertyBlockIsResetWhereTheBlockIsCleared()
        {
            Assert.That(MemosNotResetWithTheBlock(RendererCode()), Is.Empty);
        }

        [Test]
        public void MemoCheckRejectsAMemoLeftStale()
        {
            // _LodLevels' memo kept after the clear: the level count is never sent again (cracked seams).
            string old = "int _sentLevelCount; GraphicsBuffer _boundSnowDepth;\n" +
                         "public void ReleaseGpuResources() { _props?.Clear(); _boundSnowDepth = null; }\n" +
                         "void PushLevels() { if (count != _sentLevelCount) { SetVector(Ids.LodLevels, v); _sentLevelCount = count; } }";
            Assert.That(MemosNotResetWithTheBlock(old), Is.EqualTo(new[] { "_sentLevelCount is not reset in ReleaseGpuResources, which clears the property block" }));
            string twice = "void A() { _props.Clear(); _sent = default; } void B() { _props?.Clear(); }";
            Assert.That(MemosNotResetWithTheBlock(twice), Does.Contain("the property block is cleared in 2 places, not one"));
            Assert.That(MemosNotResetWithTheBlock("void ClearPropertyBlock() { _props?.Clear(); _sent = default; } void P() { if (_sent.levelCount != n) _sent.levelCount = n; }"), Is.Empty);
        }
    }
}
