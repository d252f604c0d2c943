//! The simulated machine: what a software card cannot know about the machine around it.

pub mod config;
