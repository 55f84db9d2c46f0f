using System;
using System.Collections.Generic;
using System.Globalization;

namespace GregoryTerrain
{
    /// <summary>Which side of a shared edge keeps its interior points when <see cref="G1Builder.MakeG1Edges"/> joins it.</summary>
    internal enum EdgeRule
    {
        /// <summary>The lower-index patch (left, below) keeps its inner vectors, as <see cref="G1Builder.MakeG1"/> does.</summary>
        KeepLow,
        /// <summary>The higher-index patch (right, above) keeps its inner vectors: the other side is the one being edited.</summary>
        KeepHigh,
        /// <summary>Both sides move by the least change that makes the edge G1 (a brush: no side is preferred).</summary>
        Symmetric,
    }

    /// <summary>One shared edge of a grid for <see cref="G1Builder.MakeG1Edges"/>: the patches either side, which kind, which side keeps.</summary>
    internal readonly struct SharedEdge
    {
        /// <summary>The left (vertical edge) or lower (horizontal edge) patch.</summary>
        public readonly GregoryPatch Low;
        /// <summary>The right or upper patch.</summary>
        public readonly GregoryPatch High;
        /// <summary>True for an edge on a vertical grid line (Low's u = 1 is High's u = 0), false for a horizontal one.</summary>
        public readonly bool Vertical;
        /// <summary>Which side keeps its inner vectors.</summary>
        public readonly EdgeRule Rule;
        /// <summary>Names the edge in error messages, e.g. "edge between patch (1, 2) and patch (2, 2)".</summary>
        public readonly string Where;

        /// <summary>An edge between <paramref name="low"/> and <paramref name="high"/>.</summary>
        public SharedEdge(GregoryPatch low, GregoryPatch high, bool vertical, EdgeRule rule, string where)
        {
            Low = low ?? throw new ArgumentNullException(nameof(low));
            High = high ?? throw new ArgumentNullException(nameof(high));
            Vertical = vertical;
            Rule = rule;
            Where = where;
        }
    }

    internal static partial class G1Builder
    {
        /// <summary>
        /// <see cref="MakeG1"/> on the listed edges only, for edits that change a few patches: an edge's
        /// new interior points depend only on the two patches' points along it (edge points and the
        /// boundary points next to its ends), and each edge writes interior slots no other edge
        /// writes, so joining a subset gives those edges exactly what a whole-grid run would and
        /// leaves every other point alone. Corner tangent planes must be consistent at both ends of
        /// each edge (see MakeG1); every edge is solved and checked before any point is written, so a
        /// throw changes nothing.
        /// </summary>
        public static void MakeG1Edges(IReadOnlyList<SharedEdge> edges, double relativeTolerance = 1e-9)
        {
            if (edges == null) throw new ArgumentNullException(nameof(edges));
            if (!(relativeTolerance >= 0))
                throw new ArgumentException(string.Format(CultureInfo.InvariantCulture, "relativeTolerance = {0} must be >= 0.", relativeTolerance), nameof(relativeTolerance));
            var jobs = new EdgeJob[edges.Count];
            for (int e = 0; e < edges.Count; e++)
            {
                SharedEdge s = edges[e];
                PatchSide lowSide = s.Vertical ? PatchSide.U1 : PatchSide.V1, highSide = s.Vertical ? PatchSide.U0 : PatchSide.V0;
                jobs[e] = s.Rule == EdgeRule.KeepHigh
                    ? Prepare(s.High, highSide, s.Low, lowSide, s.Where, relativeTolerance, false)
                    : Prepare(s.Low, lowSide, s.High, highSide, s.Where, relativeTolerance, s.Rule == EdgeRule.Symmetric);
            }
            for (int e = 0; e < jobs.Length; e++) jobs[e].Apply();
        }
    }
}
