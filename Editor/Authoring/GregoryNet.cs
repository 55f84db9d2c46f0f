using System;

namespace GregoryTerrain
{
    /// <summary>
    /// The G1 Gregory nets of a height field on a uniform P x Q grid of the unit square (x, y linear
    /// in u, v; only z free), as a vector of unknowns that satisfies G1 by construction:
    /// <list type="bullet">
    /// <item>per grid vertex: its height z and the offsets dx, dy of the boundary points next to it
    /// (<c>dx = (width / 3) dz/dx</c>, in height units). G1 at a vertex needs the four edge points
    /// around it in one plane with it, so a vertex has exactly these 3 degrees of freedom: no twist
    /// (the Gregory interior pairs are what frees the twist);</item>
    /// <item>per grid edge: two cross-boundary offsets e1, e2 (<c>(width / 3)</c> times the slope
    /// across the edge at its thirds). The interior point of each pair that sees this edge sits at
    /// edge point + e on one side and edge point - e on the other, so both patches have the same
    /// cross-boundary derivative all along the edge (G1 with k = -1, h = 0 for equal widths).</item>
    /// </list>
    /// That is <c>3 (P+1)(Q+1) + 2 (P+1) Q + 2 P (Q+1)</c> unknowns, about 7 a patch (the C1 spline has
    /// 4, the bilinear baseline's lattice 9). The C1 splines are the nets whose pairs coincide.
    /// Layout: vertex (i, j) at <c>3 (j (P+1) + i)</c> (z, dx, dy); the edge on x line i between y
    /// lines j, j+1 at <c>VerticalBase + 2 (j (P+1) + i)</c>; the edge on y line j between x lines i,
    /// i+1 at <c>HorizontalBase + 2 (j P + i)</c>.
    /// </summary>
    internal readonly struct GregoryNet
    {
        /// <summary>Unknowns one patch's heights depend on.</summary>
        public const int LocalCount = 20;

        public int Columns { get; }
        public int Rows { get; }
        public int VerticalBase => 3 * (Columns + 1) * (Rows + 1);
        public int HorizontalBase => VerticalBase + 2 * (Columns + 1) * Rows;
        public int Count => HorizontalBase + 2 * Columns * (Rows + 1);

        public GregoryNet(int columns, int rows)
        {
            if (columns < 1) throw new ArgumentException($"columns = {columns}, need at least 1.", nameof(columns));
            if (rows < 1) throw new ArgumentException($"rows = {rows}, need at least 1.", nameof(rows));
            Columns = columns;
            Rows = rows;
        }

        /// <summary>Index of vertex (i, j)'s z; dx, dy follow.</summary>
        public int Vertex(int i, int j) => 3 * (j * (Columns + 1) + i);
        /// <summary>Index of e1 of the edge on x line i between y lines j and j + 1; e2 follows.</summary>
        public int VerticalEdge(int i, int j) => VerticalBase + 2 * (j * (Columns + 1) + i);
        /// <summary>Index of e1 of the edge on y line j between x lines i and i + 1; e2 follows.</summary>
        public int HorizontalEdge(int i, int j) => HorizontalBase + 2 * (j * Columns + i);

        // Local unknowns of patch (i, j): 0..11 the vertices (i, j), (i+1, j), (i, j+1), (i+1, j+1),
        // each (z, dx, dy); 12, 13 the bottom edge's e1, e2; 14, 15 the top's; 16, 17 the left's; 18, 19 the right's.
        // Each of the 20 slots is a sum of up to 3 local unknowns with signs +-1 (class comment);
        // each entry is +-(local + 1): the local unknown and its sign.
        static readonly sbyte[][] SlotTerms =
        {
            // slot 0..15 = grid position (a, b), a along u; then the second points 16..19.
            new sbyte[] { +1 },               // 0  (0,0): z00
            new sbyte[] { +1, +3 },           // 1  (0,1): z00 + dy00
            new sbyte[] { +7, -9 },           // 2  (0,2): z01 - dy01
            new sbyte[] { +7 },               // 3  (0,3): z01
            new sbyte[] { +1, +2 },           // 4  (1,0): z00 + dx00
            new sbyte[] { +1, +2, +13 },      // 5  first (1,1): z00 + dx00 + eb1
            new sbyte[] { +7, +8, -15 },      // 6  first (1,2): z01 + dx01 - et1
            new sbyte[] { +7, +8 },           // 7  (1,3): z01 + dx01
            new sbyte[] { +4, -5 },           // 8  (2,0): z10 - dx10
            new sbyte[] { +4, -5, +14 },      // 9  first (2,1): z10 - dx10 + eb2
            new sbyte[] { +10, -11, -16 },    // 10 first (2,2): z11 - dx11 - et2
            new sbyte[] { +10, -11 },         // 11 (2,3): z11 - dx11
            new sbyte[] { +4 },               // 12 (3,0): z10
            new sbyte[] { +4, +6 },           // 13 (3,1): z10 + dy10
            new sbyte[] { +10, -12 },         // 14 (3,2): z11 - dy11
            new sbyte[] { +10 },              // 15 (3,3): z11
            new sbyte[] { +1, +3, +17 },      // 16 second (1,1): z00 + dy00 + el1
            new sbyte[] { +7, -9, +18 },      // 17 second (1,2): z01 - dy01 + el2
            new sbyte[] { +4, +6, -19 },      // 18 second (2,1): z10 + dy10 - er1
            new sbyte[] { +10, -12, -20 },    // 19 second (2,2): z11 - dy11 - er2
        };

        /// <summary>The global indices of patch (i, j)'s 20 local unknowns.</summary>
        public void LocalUnknowns(int i, int j, Span<int> index)
        {
            int v00 = Vertex(i, j), v10 = Vertex(i + 1, j), v01 = Vertex(i, j + 1), v11 = Vertex(i + 1, j + 1);
            for (int k = 0; k < 3; k++)
            {
                index[k] = v00 + k;
                index[3 + k] = v10 + k;
                index[6 + k] = v01 + k;
                index[9 + k] = v11 + k;
            }
            int eb = HorizontalEdge(i, j), et = HorizontalEdge(i, j + 1), el = VerticalEdge(i, j), er = VerticalEdge(i + 1, j);
            index[12] = eb; index[13] = eb + 1;
            index[14] = et; index[15] = et + 1;
            index[16] = el; index[17] = el + 1;
            index[18] = er; index[19] = er + 1;
        }

        /// <summary>
        /// The weights of the 20 local unknowns in the patch's height at (u, v): the Gregory basis
        /// (<see cref="GregoryBasis"/>) mapped through the slots' sums.
        /// </summary>
        public static void LocalWeights(double u, double v, Span<double> local)
        {
            Span<double> w = stackalloc double[GregoryBasis.WeightCount];
            Span<double> wu = stackalloc double[GregoryBasis.WeightCount];
            Span<double> wv = stackalloc double[GregoryBasis.WeightCount];
            GregoryBasis.Weights(u, v, w, wu, wv);
            local.Clear();
            for (int s = 0; s < GregoryPatch.SlotCount; s++)
            {
                sbyte[] t = SlotTerms[s];
                for (int k = 0; k < t.Length; k++)
                {
                    int e = t[k];
                    if (e > 0) local[e - 1] += w[s];
                    else local[-e - 1] -= w[s];
                }
            }
        }

        /// <summary>
        /// The transpose of <see cref="SlotHeights"/>: adds to local[k] the signed sum of the slot
        /// values that unknown k takes part in (a right-hand side from per-slot moments), in slot order.
        /// </summary>
        public static void SlotsToLocal(ReadOnlySpan<double> slotValues, Span<double> local)
        {
            for (int s = 0; s < GregoryPatch.SlotCount; s++)
            {
                sbyte[] t = SlotTerms[s];
                for (int k = 0; k < t.Length; k++)
                {
                    int e = t[k];
                    if (e > 0) local[e - 1] += slotValues[s];
                    else local[-e - 1] -= slotValues[s];
                }
            }
        }

        /// <summary>The 20 slots' heights from the patch's 20 local unknown values.</summary>
        public static void SlotHeights(ReadOnlySpan<double> local, Span<double> slots)
        {
            for (int s = 0; s < GregoryPatch.SlotCount; s++) slots[s] = SlotHeight(s, local);
        }

        /// <summary>Slot s's height from the patch's 20 local unknown values.</summary>
        static double SlotHeight(int s, ReadOnlySpan<double> local)
        {
            sbyte[] t = SlotTerms[s];
            double z = 0;
            for (int k = 0; k < t.Length; k++)
            {
                int e = t[k];
                z += e > 0 ? local[e - 1] : -local[-e - 1];
            }
            return z;
        }

        /// <summary>The P x Q Gregory grid on uniform lines with the heights of <paramref name="x"/>.</summary>
        public PatchGrid ToPatchGrid(double[] x)
        {
            if (x == null) throw new ArgumentNullException(nameof(x));
            if (x.Length != Count) throw new ArgumentException($"x.Length = {x.Length}, need {Count}.", nameof(x));
            PatchGrid grid = PatchGrid.CreateFlat(Columns, Rows);
            Span<int> index = stackalloc int[LocalCount];
            Span<double> local = stackalloc double[LocalCount];
            for (int j = 0; j < Rows; j++)
                for (int i = 0; i < Columns; i++)
                {
                    LocalUnknowns(i, j, index);
                    for (int k = 0; k < LocalCount; k++) local[k] = x[index[k]];
                    GregoryPatch p = grid.Patch(i, j);
                    for (int s = 0; s < GregoryPatch.SlotCount; s++)
                        p[s] = new Double3(p[s].x, p[s].y, SlotHeight(s, local));
                }
            return grid;
        }

        /// <summary>
        /// The C1 spline's right-hand side <c>S_y^T Z S_x</c> from the Gregory one <c>S^T z</c>: the
        /// splines are the nets <c>x = T c</c> (per vertex z, dx, dy as they are; an edge's offsets
        /// are the slope across plus or minus the twist at its ends), so <c>S_spline = S T</c> and its
        /// right-hand side is <c>T^T (S^T z)</c>, with no second pass over the samples. Layout of
        /// <see cref="SplineSurface.Coefficients"/>: <c>[(2 j + a) (2 P + 2) + 2 i + b]</c>, a, b in {0, 1}.
        /// </summary>
        public double[] SplineRightHandSide(double[] rhs)
        {
            int P = Columns, Q = Rows, nx = 2 * (P + 1);
            var v = new double[2 * (Q + 1) * nx];
            for (int j = 0; j <= Q; j++)
                for (int i = 0; i <= P; i++)
                {
                    int o = Vertex(i, j);
                    double z = rhs[o], dx = rhs[o + 1], dy = rhs[o + 2], twist = 0;
                    // EY(i, j, 1) = dy(i, j) + t(i, j); EY(i-1, j, 2) = dy(i, j) - t(i, j).
                    if (i < P) { double e = rhs[HorizontalEdge(i, j)]; dy += e; twist += e; }
                    if (i > 0) { double e = rhs[HorizontalEdge(i - 1, j) + 1]; dy += e; twist -= e; }
                    // EX(i, j, 1) = dx(i, j) + t(i, j); EX(i, j-1, 2) = dx(i, j) - t(i, j).
                    if (j < Q) { double e = rhs[VerticalEdge(i, j)]; dx += e; twist += e; }
                    if (j > 0) { double e = rhs[VerticalEdge(i, j - 1) + 1]; dx += e; twist -= e; }
                    v[(2 * j) * nx + 2 * i] = z;
                    v[(2 * j) * nx + 2 * i + 1] = dx;
                    v[(2 * j + 1) * nx + 2 * i] = dy;
                    v[(2 * j + 1) * nx + 2 * i + 1] = twist;
                }
            return v;
        }

        /// <summary>
        /// x = T c: the net of a C1 spline with coefficients c (layout of
        /// <see cref="SplineSurface.Coefficients"/>): vertices' z, dx, dy as they are, an edge's
        /// offsets the slope across it plus the twist at its start and minus the one at its end.
        /// The transpose of <see cref="SplineRightHandSide"/>.
        /// </summary>
        public void FromSpline(double[] c, double[] x)
        {
            int P = Columns, Q = Rows, nx = 2 * (P + 1);
            double C(int ky, int kx) => c[ky * nx + kx];
            for (int j = 0; j <= Q; j++)
                for (int i = 0; i <= P; i++)
                {
                    int o = Vertex(i, j);
                    x[o] = C(2 * j, 2 * i);
                    x[o + 1] = C(2 * j, 2 * i + 1);
                    x[o + 2] = C(2 * j + 1, 2 * i);
                }
            for (int j = 0; j < Q; j++)
                for (int i = 0; i <= P; i++)
                {
                    int o = VerticalEdge(i, j);
                    x[o] = C(2 * j, 2 * i + 1) + C(2 * j + 1, 2 * i + 1);
                    x[o + 1] = C(2 * j + 2, 2 * i + 1) - C(2 * j + 3, 2 * i + 1);
                }
            for (int j = 0; j <= Q; j++)
                for (int i = 0; i < P; i++)
                {
                    int o = HorizontalEdge(i, j);
                    x[o] = C(2 * j + 1, 2 * i) + C(2 * j + 1, 2 * i + 1);
                    x[o + 1] = C(2 * j + 1, 2 * i + 2) - C(2 * j + 1, 2 * i + 3);
                }
        }

        /// <summary>
        /// The unknowns of a C1 Bezier net ((3P + 1) x (3Q + 1) heights, row-major along y): each
        /// offset is a difference of the net's points next to the vertex or edge (taken inwards, or
        /// from the last patch at the grid's far borders). Exact for a C1 net.
        /// </summary>
        public double[] FromBezierNet(double[] net)
        {
            int bx = 3 * Columns + 1, by = 3 * Rows + 1;
            if (net == null) throw new ArgumentNullException(nameof(net));
            if (net.Length != bx * by) throw new ArgumentException($"net.Length = {net.Length}, need {bx} x {by}.", nameof(net));
            double N(int a, int b) => net[b * bx + a];
            double Dx(int a, int b) => a < bx - 1 ? N(a + 1, b) - N(a, b) : N(a, b) - N(a - 1, b);
            double Dy(int a, int b) => b < by - 1 ? N(a, b + 1) - N(a, b) : N(a, b) - N(a, b - 1);
            var x = new double[Count];
            for (int j = 0; j <= Rows; j++)
                for (int i = 0; i <= Columns; i++)
                {
                    int o = Vertex(i, j);
                    x[o] = N(3 * i, 3 * j);
                    x[o + 1] = Dx(3 * i, 3 * j);
                    x[o + 2] = Dy(3 * i, 3 * j);
                }
            for (int j = 0; j < Rows; j++)
                for (int i = 0; i <= Columns; i++)
                    for (int k = 1; k <= 2; k++) x[VerticalEdge(i, j) + k - 1] = Dx(3 * i, 3 * j + k);
            for (int j = 0; j <= Rows; j++)
                for (int i = 0; i < Columns; i++)
                    for (int k = 1; k <= 2; k++) x[HorizontalEdge(i, j) + k - 1] = Dy(3 * i + k, 3 * j);
            return x;
        }
    }
}
