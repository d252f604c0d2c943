// The examples manual's GeneralMotion sequence (§10) from C#: a line to (10, 10), an arc
// through (10, 20) to (20, 20) (centre (15, 15), clockwise), a full circle about (25, 20),
// ending at (20, 20) = 10000 pulses per axis at 500 pulses/UU; every point of the arc lies
// on its circle of radius sqrt(50), read in whole pulses toward 0 (within sqrt(2)/500 UU).
// Runs on MCCL_CLOCK=fast (run.sh sets it).
using System;

public static class GeneralMotionTests
{
    static void WaitStop(ushort g)
    {
        int n = 0;
        while (MCCL.MCC_GetMotionStatus(g) != MCCL.GMS_STOP && n++ < 1000000)
            MCCL.MCC_TimeDelay(1);
    }

    [MonoTest(300)]
    public static void GeneralMotionSequence()
    {
        Check.Eq(Fixture.InitOneCard(), MCCL.NO_ERR, "InitSystem");
        const ushort g = 0;
        Check.Eq(MCCL.MCC_SetFeedSpeed(10, g), 10.0, "SetFeedSpeed");
        Check.Eq(MCCL.MCC_Line(10, 10, 0, 0, 0, 0, 0, 0, g, MCCL.IMP_AXIS_ALL), 0, "Line index");
        Check.Eq(MCCL.MCC_ArcXY(10, 20, 20, 20, g), 1, "ArcXY index");
        Check.Eq(MCCL.MCC_CircleXY(25, 20, (byte)MCCL.CIR_CW, g), 2, "CircleXY index");
        double x = 0, y = 0, z = 0, u = 0, v = 0, w = 0, a = 0, b = 0;
        // Sample the path: after the line (1.715 s and its end period), every point of the
        // arc is on its circle.
        MCCL.MCC_TimeDelay(1800);
        double worst = 0;
        for (int i = 0; i < 20; i++)
        {
            MCCL.MCC_GetCurPos(ref x, ref y, ref z, ref u, ref v, ref w, ref a, ref b, g);
            worst = Math.Max(worst, Math.Abs(Math.Sqrt((x - 15) * (x - 15) + (y - 15) * (y - 15)) - Math.Sqrt(50)));
            MCCL.MCC_TimeDelay(100);
        }
        Check.True(worst <= Math.Sqrt(2) / 500, "arc points on the circle (worst " + worst + ")");
        WaitStop(g);
        Check.Eq(MCCL.MCC_GetCurPos(ref x, ref y, ref z, ref u, ref v, ref w, ref a, ref b, g), MCCL.NO_ERR, "GetCurPos");
        Check.True(Math.Abs(x - 20) < 1e-9 && Math.Abs(y - 20) < 1e-9 && z == 0, "ends at (20, 20, 0): " + x + ", " + y);
        int lx = 0, ly = 0, lz = 0, lu = 0, lv = 0, lw = 0, la = 0, lb = 0;
        Check.Eq(MCCL.MCC_GetPulsePos(ref lx, ref ly, ref lz, ref lu, ref lv, ref lw, ref la, ref lb, g), MCCL.NO_ERR, "GetPulsePos");
        Check.Eq(lx, 10000, "X pulses");
        Check.Eq(ly, 10000, "Y pulses");
        // A collinear arc is queued, as the vendor's library takes it, and fails when it
        // starts: error record 0xF104.
        Check.Eq(MCCL.MCC_ArcXY(15, 15, 10, 10, g), 3, "collinear arc queued");
        MCCL.MCC_TimeDelay(1);
        Check.Eq(MCCL.MCC_GetErrorCode(g), 0xF104, "bad arc recorded");
        Check.Eq(MCCL.MCC_ClearError(g), MCCL.NO_ERR, "ClearError");
        Check.Eq(MCCL.MCC_CloseSystem(), MCCL.NO_ERR, "CloseSystem");
    }
}
