//! Tests of the samplers: each one's defining property.
