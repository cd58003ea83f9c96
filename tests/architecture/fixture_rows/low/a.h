// the lowest layer of the fixture: includes nothing
#pragma once
