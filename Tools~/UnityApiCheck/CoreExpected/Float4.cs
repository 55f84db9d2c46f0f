namespace GregoryTerrain
{
    // As in core-range's Float4.cs.
    public struct Float4 { public float x, y, z, w; public Float4(float x, float y, float z, float w) { this.x = x; this.y = y; this.z = z; this.w = w; } }
}
