use super::*;

#[test]
fn limit_masks_follow_section_6_5() {
    // Guide example: dir 0 on bit 3 high, dir 1 on bit 5 low
    // -> 0L2,8,0,32,32.
    assert_eq!(limit_masks(3, true), Some((8, 0)));
    assert_eq!(limit_masks(5, false), Some((32, 32)));
    assert_eq!(limit_masks(-1, true), Some((0, 0)));
    assert_eq!(limit_masks(6, true), None);
    assert_eq!(limit_masks(-2, false), None);
}

#[test]
fn com_port_rule() {
    assert_eq!(com_port_path(0), None);
    // Use a port number nobody sets.
    assert_eq!(com_port_path(77), Some(::mc3b::serial::com_port_device(77)));
}
