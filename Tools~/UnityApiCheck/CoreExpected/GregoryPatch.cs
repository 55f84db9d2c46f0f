namespace GregoryTerrain
{
    // As in core-patch's GregoryPatch.cs.
    public sealed class GregoryPatch
    {
        public const int SlotCount = 20;
        public readonly Double3[] Points = new Double3[SlotCount];
        public Double3 this[int slot] { get => Points[slot]; set => Points[slot] = value; }
    }
}
