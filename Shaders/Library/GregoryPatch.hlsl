#ifndef GT_GREGORY_PATCH_INCLUDED
#define GT_GREGORY_PATCH_INCLUDED

// Slot layout of a Gregory patch's 20 control points; mirrors GregoryPatch.cs (internals.md).
// Slots 0..15: the 4x4 grid k = 4 i + j (i along u, j along v). Interior slots 5, 6, 9, 10 hold the
// first point of each pair (P110, P120, P210, P220); slots 16..19 the second (P111, P121, P211, P221).

#define GREGORY_SLOT_COUNT 20

#define GREGORY_CORNER00 0
#define GREGORY_CORNER03 3
#define GREGORY_CORNER30 12
#define GREGORY_CORNER33 15

#define GREGORY_P110 5
#define GREGORY_P120 6
#define GREGORY_P210 9
#define GREGORY_P220 10
#define GREGORY_P111 16
#define GREGORY_P121 17
#define GREGORY_P211 18
#define GREGORY_P221 19

// Slot of grid position (i, j), i along u, j along v, both in 0..3.
uint GregoryPatchSlot(uint i, uint j)
{
    return 4u * i + j;
}

#endif // GT_GREGORY_PATCH_INCLUDED
