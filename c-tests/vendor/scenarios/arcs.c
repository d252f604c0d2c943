/* Arcs, circles and helices: every plane, both directions, three-point, centre-angle and
 * circle forms, with auxiliary axes, and arcs whose geometry is bad. */
#include "common.h"

STD_SETUP(std3, 10000, 1, 3)
STD_SETUP(std5, 10000, 1, 5)

#define ARC_CASE(name, type, call)                                                         \
    static void name(int t)                                                                \
    {                                                                                      \
        if (t == 0) {                                                                      \
            vd_profile(type, 50, 50, 10);                                                  \
            call;                                                                          \
        }                                                                                  \
    }

/* Three-point arcs: from the origin through a point to an end. */
ARC_CASE(arc_xy_ccw, 'T', CI(MCC_ArcXY, 1, -1, 2, 0, 0))     /* below: counter-clockwise */
ARC_CASE(arc_xy_cw, 'T', CI(MCC_ArcXY, 1, 1, 2, 0, 0))       /* above: clockwise */
ARC_CASE(arc_xy_s, 'S', CI(MCC_ArcXY, 0.5, 0.2, 1, 1, 0))
ARC_CASE(arc_yz_ccw, 'T', CI(MCC_ArcYZ, 1, -1, 2, 0, 0))
ARC_CASE(arc_yz_cw, 'T', CI(MCC_ArcYZ, 1, 1, 2, 0, 0))
ARC_CASE(arc_zx_ccw, 'T', CI(MCC_ArcZX, 1, -1, 2, 0, 0))
ARC_CASE(arc_zx_cw, 'T', CI(MCC_ArcZX, 1, 1, 2, 0, 0))
ARC_CASE(arc_xyz, 'T', CI(MCC_ArcXYZ, 1, 1, 1, 2, 0, 2, 0))
ARC_CASE(arc_xy_small, 'T', CI(MCC_ArcXY, 0.001, 0.001, 0.002, 0, 0))
ARC_CASE(arc_xy_large, 'T', CI(MCC_ArcXY, 3, 3, 6, 0, 0))
/* Centre and angle. */
ARC_CASE(arctheta_xy_pos, 'T', CI(MCC_ArcThetaXY, 1, 0, 90, 0))
ARC_CASE(arctheta_xy_neg, 'T', CI(MCC_ArcThetaXY, 1, 0, -90, 0))
ARC_CASE(arctheta_yz_pos, 'T', CI(MCC_ArcThetaYZ, 1, 0, 120, 0))
ARC_CASE(arctheta_yz_neg, 'S', CI(MCC_ArcThetaYZ, 0, 1, -45, 0))
ARC_CASE(arctheta_zx_pos, 'T', CI(MCC_ArcThetaZX, 1, 0, 180, 0))
ARC_CASE(arctheta_zx_neg, 'T', CI(MCC_ArcThetaZX, 0.5, 0.5, -270, 0))
ARC_CASE(arctheta_xy_720, 'T', CI(MCC_ArcThetaXY, 0.2, 0, 720, 0))
/* Circles. */
ARC_CASE(circle_xy_ccw, 'T', CI(MCC_CircleXY, 0.5, 0, CIR_CCW, 0))
ARC_CASE(circle_xy_cw, 'T', CI(MCC_CircleXY, 0.5, 0, CIR_CW, 0))
ARC_CASE(circle_xy_s, 'S', CI(MCC_CircleXY, 0, 0.4, CIR_CCW, 0))
ARC_CASE(circle_yz_ccw, 'T', CI(MCC_CircleYZ, 0.5, 0, CIR_CCW, 0))
ARC_CASE(circle_yz_cw, 'T', CI(MCC_CircleYZ, 0, 0.5, CIR_CW, 0))
ARC_CASE(circle_zx_ccw, 'T', CI(MCC_CircleZX, 0.5, 0, CIR_CCW, 0))
ARC_CASE(circle_zx_cw, 'T', CI(MCC_CircleZX, 0.3, 0.4, CIR_CW, 0))
/* Helices. */
ARC_CASE(helical_xy_z, 'T', CI(MCC_HelicalXY_Z, 0.5, 0, 0.2, 360, 0))
ARC_CASE(helical_xy_z_neg, 'T', CI(MCC_HelicalXY_Z, 0.5, 0, 0.2, -180, 0))
ARC_CASE(helical_yz_x, 'T', CI(MCC_HelicalYZ_X, 0.5, 0, -0.3, 270, 0))
ARC_CASE(helical_zx_y, 'S', CI(MCC_HelicalZX_Y, 0, 0.5, 0.1, 360, 0))
ARC_CASE(helica_xy_z_old, 'T', CI(MCC_HelicaXY_Z, 0.5, 0, 0.4, 0.2, CIR_CCW, 0))
/* Bad geometry. */
ARC_CASE(arc_collinear, 'T', CI(MCC_ArcXY, 1, 0, 2, 0, 0))
ARC_CASE(arc_end_at_start, 'T', CI(MCC_ArcXY, 1, 1, 0, 0, 0))
ARC_CASE(arc_ref_at_start, 'T', CI(MCC_ArcXY, 0, 0, 1, 1, 0))
ARC_CASE(circle_center_at_start, 'T', CI(MCC_CircleXY, 0, 0, CIR_CW, 0))
ARC_CASE(arctheta_zero, 'T', CI(MCC_ArcThetaXY, 1, 0, 0, 0))
ARC_CASE(arc_bad_dir, 'T', CI(MCC_CircleXY, 0.5, 0, 7, 0))

/* Auxiliary axes along an arc. */
static void arc_xy_aux(int t)
{
    if (t == 0) {
        vd_profile('T', 50, 50, 10);
        CI(MCC_ArcXY_Aux, 1, -1, 2, 0, 1, -0.5, 0, 0, 0, 0);
    }
}

static void circle_xy_aux(int t)
{
    if (t == 0) {
        vd_profile('T', 50, 50, 10);
        CI(MCC_CircleXY_Aux, 0.5, 0, 0.5, 0.25, 0, 0, 0, CIR_CCW, 0);
    }
}

static void helical_xy_z_aux(int t)
{
    if (t == 0) {
        vd_profile('T', 50, 50, 10);
        CI(MCC_HelicalXY_Z_Aux, 0.5, 0, 0.2, 1, 0.5, 0, 0, 0, 360, 0);
    }
}

/* An arc after a line, and a line after the arc; a bad arc in the middle of a queue: the
 * error record and what the next command returns. */
static void arc_in_sequence(int t)
{
    if (t == 0) {
        vd_profile('T', 40, 40, 10);
        LINE(0, 1, 0, 0);
        CI(MCC_ArcXY, 2, 1, 1, 2, 0);
        LINE(0, 0, 2, 0);
    }
}

static void arc_bad_in_queue(int t)
{
    if (t == 0) {
        vd_profile('T', 40, 40, 10);
        LINE(0, 1, 0, 0);
        CI(MCC_ArcXY, 2, 0, 3, 0, 0);
        LINE(0, 0, 2, 0);
    }
    if (t == 300) {
        LINE(0, 0, 0, 0);
        vd_dump_group(0);
    }
    if (t == 310) {
        CI(MCC_ClearError, 0);
        LINE(0, 0, 0, 0);
    }
}

static void arc_collinear_then_line(int t)
{
    if (t == 0) {
        vd_profile('T', 40, 40, 10);
        CI(MCC_ArcXY, 1, 0, 2, 0, 0);
    }
    if (t == 1 || t == 2 || t == 5)
        LINE(0, 1, 1, 0);
    if (t == 10)
        CI(MCC_ClearError, 0);
    if (t == 11)
        LINE(0, 1, 1, 0);
}

static void arc_blend(int t)
{
    if (t == 0) {
        vd_profile('T', 40, 40, 10);
        CI(MCC_EnableBlend, 0);
        LINE(0, 1, 0, 0);
        CI(MCC_ArcXY, 2, 1, 1, 2, 0);
        LINE(0, 0, 2, 0);
    }
}

const Scenario vd_arcs[] = {
    SCEN(arc_xy_ccw, std3, 0, 4000),
    SCEN(arc_xy_cw, std3, 0, 4000),
    SCEN(arc_xy_s, std3, 0, 4000),
    SCEN(arc_yz_ccw, std3, 0, 4000),
    SCEN(arc_yz_cw, std3, 0, 4000),
    SCEN(arc_zx_ccw, std3, 0, 4000),
    SCEN(arc_zx_cw, std3, 0, 4000),
    SCEN(arc_xyz, std3, 0, 4000),
    SCEN(arc_xy_small, std3, 0, 4000),
    SCEN(arc_xy_large, std3, 0, 4000),
    SCEN(arctheta_xy_pos, std3, 0, 4000),
    SCEN(arctheta_xy_neg, std3, 0, 4000),
    SCEN(arctheta_yz_pos, std3, 0, 4000),
    SCEN(arctheta_yz_neg, std3, 0, 4000),
    SCEN(arctheta_zx_pos, std3, 0, 4000),
    SCEN(arctheta_zx_neg, std3, 0, 4000),
    SCEN(arctheta_xy_720, std3, 0, 4000),
    SCEN(circle_xy_ccw, std3, 0, 4000),
    SCEN(circle_xy_cw, std3, 0, 4000),
    SCEN(circle_xy_s, std3, 0, 4000),
    SCEN(circle_yz_ccw, std3, 0, 4000),
    SCEN(circle_yz_cw, std3, 0, 4000),
    SCEN(circle_zx_ccw, std3, 0, 4000),
    SCEN(circle_zx_cw, std3, 0, 4000),
    SCEN(helical_xy_z, std3, 0, 4000),
    SCEN(helical_xy_z_neg, std3, 0, 4000),
    SCEN(helical_yz_x, std3, 0, 4000),
    SCEN(helical_zx_y, std3, 0, 4000),
    SCEN(helica_xy_z_old, std3, 0, 4000),
    SCEN(arc_collinear, std3, 0, 500),
    SCEN(arc_end_at_start, std3, 0, 2000),
    SCEN(arc_ref_at_start, std3, 0, 2000),
    SCEN(circle_center_at_start, std3, 0, 2000),
    SCEN(arctheta_zero, std3, 0, 2000),
    SCEN(arc_bad_dir, std3, 0, 2000),
    SCEN(arc_xy_aux, std5, 0, 4000),
    SCEN(circle_xy_aux, std5, 0, 4000),
    SCEN(helical_xy_z_aux, std5, 0, 4000),
    SCEN(arc_in_sequence, std3, 0, 4000),
    SCEN(arc_bad_in_queue, std3, 310, 4000),
    SCEN(arc_collinear_then_line, std3, 11, 2000),
    SCEN(arc_blend, std3, 0, 4000),
    SCEN_END,
};
