namespace GregoryTerrain
{
    // EXPECTED: returns a new grid whose interior points satisfy eq. 7-9 on every shared edge.
    public static class G1Builder
    {
        public static PatchGrid Enforce(PatchGrid grid) => grid;
    }
}
