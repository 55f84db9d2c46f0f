using System;
using System.Globalization;

namespace GregoryTerrain
{
    /// <summary>
    /// One bicubic Gregory patch: 20 control points in terrain space, in double (the reference).
    /// Slot layout (internals.md): slots 0..15 are the 4x4 grid <c>k = 4 i + j</c> (i along u, j along v);
    /// the interior slots 5, 6, 9, 10 hold the first point of each pair (P110, P120, P210, P220) and
    /// slots 16..19 the second (P111, P121, P211, P221). With slots 16..19 equal to 5, 6, 9, 10 the
    /// patch is exactly the bicubic Bezier patch of slots 0..15.
    /// </summary>
    [Serializable]
    internal sealed class GregoryPatch
    {
        public const int SlotCount = 20;

        // Corners (the patch interpolates them): P00, P03, P30, P33.
        public const int Corner00 = 0;
        public const int Corner03 = 3;
        public const int Corner30 = 12;
        public const int Corner33 = 15;

        // Interior pairs. The first point of a pair is the one the v = const edges see (P_ij0 is the
        // blend's limit on v = 0 or v = 1); the second is the one the u = const edges see.
        public const int P110 = 5;
        public const int P120 = 6;
        public const int P210 = 9;
        public const int P220 = 10;
        public const int P111 = 16;
        public const int P121 = 17;
        public const int P211 = 18;
        public const int P221 = 19;

        /// <summary>The 20 control points, slot order above. Always length 20.</summary>
        public readonly Double3[] Points = new Double3[SlotCount];

        /// <summary>Slot of grid position (i, j) of the 4x4 net, i along u, j along v (0..3 each).</summary>
        public static int Slot(int i, int j)
        {
            if ((uint)i > 3u) throw new ArgumentOutOfRangeException(nameof(i), i, $"i = {i} must be in 0..3.");
            if ((uint)j > 3u) throw new ArgumentOutOfRangeException(nameof(j), j, $"j = {j} must be in 0..3.");
            return 4 * i + j;
        }

        /// <summary>True for the four interior grid slots (5, 6, 9, 10) that carry the first point of a pair.</summary>
        public static bool IsInteriorSlot(int slot) => slot == P110 || slot == P120 || slot == P210 || slot == P220;

        /// <summary>The slot holding the second point of the pair whose first point is <paramref name="firstSlot"/> (5, 6, 9 or 10).</summary>
        public static int SecondOfPair(int firstSlot)
        {
            switch (firstSlot)
            {
                case P110: return P111;
                case P120: return P121;
                case P210: return P211;
                case P220: return P221;
                default: throw new ArgumentOutOfRangeException(nameof(firstSlot), firstSlot, $"firstSlot = {firstSlot} is not an interior slot (5, 6, 9, 10).");
            }
        }

        public Double3 this[int slot]
        {
            get => Points[slot];
            set => Points[slot] = value;
        }

        public GregoryPatch() { }

        /// <summary>A copy of the 20 points of <paramref name="points"/> (length 20, slot order).</summary>
        public GregoryPatch(ReadOnlySpan<Double3> points)
        {
            if (points.Length != SlotCount)
                throw new ArgumentException($"points.Length = {points.Length}, a Gregory patch has {SlotCount} control points.", nameof(points));
            points.CopyTo(Points);
        }

        public GregoryPatch Clone() => new GregoryPatch(Points);

        /// <summary>
        /// The Gregory patch equal to the bicubic Bezier patch with net <paramref name="net"/>
        /// (16 points, <c>net[4 i + j]</c>): each interior pair gets the same point twice.
        /// </summary>
        public static GregoryPatch FromBezier(ReadOnlySpan<Double3> net)
        {
            if (net.Length != 16)
                throw new ArgumentException($"net.Length = {net.Length}, a bicubic Bezier net has 16 points.", nameof(net));
            var p = new GregoryPatch();
            net.CopyTo(p.Points);
            p.Points[P111] = net[P110];
            p.Points[P121] = net[P120];
            p.Points[P211] = net[P210];
            p.Points[P221] = net[P220];
            return p;
        }

        /// <summary>
        /// Throws ArgumentException unless every control point is finite. <paramref name="name"/>
        /// names the patch in the message (e.g. "patch (2, 3)").
        /// </summary>
        public void Validate(string name = "patch")
        {
            for (int k = 0; k < SlotCount; k++)
            {
                Double3 p = Points[k];
                if (!p.IsFinite)
                    throw new ArgumentException(string.Format(CultureInfo.InvariantCulture,
                        "{0} slot {1}: control point {2} is not finite.", name, k, p), name);
            }
        }

        /// <summary>
        /// The control points rounded to float (what the GPU holds), into <paramref name="destination"/>
        /// (length at least 20). Throws if a point does not fit in a float.
        /// </summary>
        public void ToFloat(Span<Float3> destination)
        {
            if (destination.Length < SlotCount)
                throw new ArgumentException($"destination.Length = {destination.Length}, need {SlotCount}.", nameof(destination));
            // Check every point before writing any, so a failure leaves destination untouched.
            for (int k = 0; k < SlotCount; k++)
            {
                if (!((Float3)Points[k]).IsFinite)
                    throw new ArgumentException(string.Format(CultureInfo.InvariantCulture,
                        "slot {0}: control point {1} is not finite in float.", k, Points[k]), nameof(destination));
            }
            for (int k = 0; k < SlotCount; k++)
                destination[k] = (Float3)Points[k];
        }
    }
}
