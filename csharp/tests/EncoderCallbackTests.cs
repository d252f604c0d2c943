// An encoder-compare callback from C# (examples manual §25): the delegate lives in a static
// field (the GC must not collect it while the library holds it), the callback runs on the
// library's engine thread, aborts the motion there and counts its calls. X runs to 100 UU at
// 10 UU/s (10 counts per tick at the 2 ms period of InitOneCard); the
// compare value 20000 fires once; the axis stops within one tick of counts past it.
using System;
using System.Threading;

public static class EncoderCallbackTests
{
    static MCCL.ENCISR s_isr;        // kept alive for as long as it is registered
    static int s_calls;
    static int s_comp0;
    static int s_abortRet = 99;
    static int s_threadId;

    static void OnEncoder(ref ENCINT e)
    {
        try
        {
            Interlocked.Increment(ref s_calls);
            if (e.COMP0 != 0)
                Interlocked.Increment(ref s_comp0);
            s_threadId = Thread.CurrentThread.ManagedThreadId;
            s_abortRet = MCCL.MCC_AbortMotionEx(0, 0);
            MCCL.MCC_DisableENCCompTrigger(0, 0);
        }
        catch (Exception)
        {
            // An exception escaping onto the engine thread would end the process.
        }
    }

    [MonoTest(400)]
    public static void CompareCallbackAbortsMotionOnce()
    {
        Check.Eq(Fixture.InitOneCard(), MCCL.NO_ERR, "InitSystem");
        s_isr = OnEncoder;
        Check.Eq(MCCL.MCC_SetENCRoutine(s_isr, 0), MCCL.NO_ERR, "SetENCRoutine");
        Check.Eq(MCCL.MCC_SetENCCompValue(20000, 0, 0), MCCL.NO_ERR, "SetENCCompValue");
        Check.Eq(MCCL.MCC_EnableENCCompTrigger(0, 0), MCCL.NO_ERR, "EnableENCCompTrigger");
        MCCL.MCC_SetFeedSpeed(10, 0);
        Check.True(MCCL.MCC_Line(100, 0, 0, 0, 0, 0, 0, 0, 0, MCCL.IMP_AXIS_ALL) >= 0, "Line");
        for (int i = 0; i < 100; i++)
            GC.Collect();                      // the delegate must survive this
        int n = 0;
        while (MCCL.MCC_GetMotionStatus(0) != MCCL.GMS_STOP && n++ < 1000000)
            MCCL.MCC_TimeDelay(1);
        int count = 0;
        Check.Eq(MCCL.MCC_GetENCValue(ref count, 0, 0), MCCL.NO_ERR, "GetENCValue");
        Check.Eq(s_calls, 1, "the callback ran once");
        Check.Eq(s_comp0, 1, "with COMP0 set");
        Check.Eq(s_abortRet, MCCL.NO_ERR, "AbortMotionEx from the callback");
        Check.True(s_threadId != Thread.CurrentThread.ManagedThreadId, "on the engine thread");
        // 10 UU/s x 2 ms x 500 counts/UU = 10 counts per tick.
        Check.True(count >= 20000 && count <= 20010, "stopped near 20000: " + count);
        Check.Eq(MCCL.MCC_SetENCRoutine(null, 0), MCCL.NO_ERR, "unregister");
        Check.Eq(MCCL.MCC_CloseSystem(), MCCL.NO_ERR, "CloseSystem");
        GC.KeepAlive(s_isr);
    }
}
