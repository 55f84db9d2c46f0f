namespace GregoryTerrain
{
    // EXPECTED: Read throws FormatException (or ArgumentException) naming the field and value.
    public static class PatchGridJson
    {
        public static string Write(PatchGrid grid) => null;
        public static PatchGrid Read(string json) => null;
    }
}
