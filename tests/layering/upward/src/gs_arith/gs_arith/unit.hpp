// An upward include for layering_check_fails: gs_arith (layer 2) must not include gs_packets (layer 4).
#pragma once
#include "gs_packets/packet.hpp"
