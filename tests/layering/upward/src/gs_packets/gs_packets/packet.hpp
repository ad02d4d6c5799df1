// The header the upward fixture includes.
#pragma once
