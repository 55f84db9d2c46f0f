using System.Collections.Generic;
namespace GregoryTerrain
{
    // EXPECTED (not yet in Core): an n x m grid of Gregory patches; the constructor validates.
    public sealed class PatchGrid
    {
        public PatchGrid(int columns, int rows, double[] xLines, double[] yLines, GregoryPatch[] patches) { }
        public int Columns => 0;
        public int Rows => 0;
        public IReadOnlyList<double> XLines => null;
        public IReadOnlyList<double> YLines => null;
        /// <summary>Patch p = j * n + i.</summary>
        public IReadOnlyList<GregoryPatch> Patches => null;
    }
}
