//! Special functions: Bessel functions of integer order and their derivatives.

pub mod bessel;
