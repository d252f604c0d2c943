//! The channels a group commands every tick: which of its axes send their pulses to
//! which channel of its card.

use super::GroupState;
use crate::config::{AXES, CARDS};

/// The axes of a group whose pulses command a channel of the group's card, each with
/// that channel, in axis order, and the card.
///
/// Several groups may map the same channel; only the last axis (in group order, then
/// axis order) mapping a channel commands it (the others' pulses would be overwritten
/// in the same tick), so only that axis is listed. Built once when the engine starts
/// (a group's channels come from its definition); the tick walks the list instead of
/// testing every axis for a mapping.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Commanded {
    /// `(axis, channel)`, each below `AXES`; the first `len` are the list.
    pairs: [(u8, u8); AXES],
    len: u8,
    /// The card of the channels (the group's), kept here so that the tick reads it with
    /// the pairs (the group's definition is on a line of its own).
    card: u8,
    /// Whether the list is every axis to the channel of its own number, `(0, 0)` to
    /// `(7, 7)`: the usual group on a card of its own, which the tick commands without
    /// looking the pairs up ([`Commanded::is_identity`]).
    identity: bool,
}

impl Commanded {
    /// The list of `pairs` `(axis, channel)` below `AXES` (others are left out) of
    /// channels on `card`, in the order given, at most `AXES` of them. A card past 255
    /// (there are at most 12) gives an empty list.
    pub fn new(card: usize, pairs: impl IntoIterator<Item = (usize, usize)>) -> Commanded {
        let Ok(card) = u8::try_from(card) else {
            return Commanded::default();
        };
        let mut c = Commanded {
            card,
            ..Commanded::default()
        };
        for (axis, chan) in pairs {
            let (Ok(a), Ok(ch)) = (u8::try_from(axis), u8::try_from(chan)) else {
                continue;
            };
            if axis < AXES && chan < AXES && usize::from(c.len) < AXES {
                c.pairs[usize::from(c.len)] = (a, ch);
                c.len += 1;
            }
        }
        c.identity = usize::from(c.len) == AXES
            && c.pairs
                .iter()
                .enumerate()
                .all(|(i, &(a, ch))| usize::from(a) == i && usize::from(ch) == i);
        c
    }

    /// Whether axis `i` commands channel `i`, for every axis.
    #[inline]
    pub fn is_identity(&self) -> bool {
        self.identity
    }

    /// Whether no axis commands a channel.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The channels, one bit each (bit n for channel n).
    pub fn channel_mask(&self) -> u8 {
        self.pairs().fold(0, |m, (_, ch)| m | 1 << ch)
    }

    /// The card of the channels.
    pub fn card(&self) -> usize {
        usize::from(self.card)
    }

    /// The `(axis, channel)` pairs. Both are below `AXES`; the remainder makes that
    /// visible to the compiler, so indexing an axis or a card's channels by them needs
    /// no bounds check (`AXES` is a power of two: the remainder is a mask).
    #[inline]
    pub fn pairs(&self) -> impl Iterator<Item = (usize, usize)> + '_ {
        self.pairs
            .iter()
            .take(usize::from(self.len))
            .map(|&(a, ch)| (usize::from(a) % AXES, usize::from(ch) % AXES))
    }
}

/// What each of `groups` commands (`GroupState::set_commanded`): per group, the axes that are the last (in group
/// order, then axis order) to map their channel, with the channel. An axis mapping
/// another card than its group's (which `engine::axes_of` never makes) commands nothing.
pub fn commanding_axes(groups: &[GroupState]) -> Vec<Commanded> {
    let mut last = [[None::<(usize, usize)>; AXES]; CARDS];
    for (n, g) in groups.iter().enumerate() {
        for (i, ax) in g.axes().iter().enumerate() {
            if let Some((card, ch)) = ax.channel {
                if let Some(c) = last.get_mut(card).and_then(|c| c.get_mut(ch)) {
                    *c = Some((n, i));
                }
            }
        }
    }
    groups
        .iter()
        .enumerate()
        .map(|(n, g)| {
            Commanded::new(
                g.def().card.0,
                g.axes().iter().enumerate().filter_map(|(i, ax)| {
                    let (card, ch) = ax.channel?;
                    let own = card == g.def().card.0;
                    let lasts = last.get(card)?.get(ch).copied().flatten() == Some((n, i));
                    (own && lasts).then_some((i, ch))
                }),
            )
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keeps_the_pairs_in_order_and_leaves_out_what_is_out_of_range() {
        let c = Commanded::new(2, [(0, 3), (9, 1), (2, 8), (7, 7), (300, 0)]);
        assert_eq!(c.pairs().collect::<Vec<_>>(), vec![(0, 3), (7, 7)]);
        assert_eq!(c.card(), 2);
        assert!(!c.is_empty());
        assert!(Commanded::new(0, []).is_empty());
        assert!(Commanded::new(256, [(0, 0)]).is_empty());
    }

    #[test]
    fn every_axis_to_its_own_channel_is_the_identity() {
        assert!(Commanded::new(1, (0..AXES).map(|i| (i, i))).is_identity());
        // Seven of the eight, one swapped, one out of range, or in another order: not.
        assert!(!Commanded::new(1, (0..AXES - 1).map(|i| (i, i))).is_identity());
        let swapped = (0..AXES).map(|i| (i, if i < 2 { 1 - i } else { i }));
        assert!(!Commanded::new(1, swapped).is_identity());
        let out = (0..AXES).map(|i| (i, if i == 7 { 8 } else { i }));
        assert!(!Commanded::new(1, out).is_identity());
        assert!(!Commanded::new(1, (0..AXES).rev().map(|i| (i, i))).is_identity());
        assert!(!Commanded::new(0, []).is_identity());
    }

    #[test]
    fn holds_at_most_axes_pairs() {
        let c = Commanded::new(0, (0..20).map(|i| (i % AXES, i % AXES)));
        assert_eq!(c.pairs().count(), AXES);
    }
}
