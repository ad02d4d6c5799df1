// An upward include for layering_check_fails: gs_arith (layer 20) must not include gs_packets (layer 40).
#pragma once
#include "gs_packets/packet.hpp"
