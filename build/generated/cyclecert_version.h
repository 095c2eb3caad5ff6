#pragma once
#define CYCLECERT_VERSION "0.1.0"
