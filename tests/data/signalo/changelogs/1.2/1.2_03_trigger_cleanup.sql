
-- https://github.com/opengisch/signalo/blob/943368c9e39eedc1b38d89b6c238de7ba091fbeb/data_model/app/vw_sign_symbol.py#L138C32-L138C70
DROP FUNCTION IF EXISTS signalo_app.ft_vw_sign_symbol_INSERT();
DROP FUNCTION IF EXISTS signalo_app.ft_vw_sign_symbol_UPDATE();
DROP FUNCTION IF EXISTS signalo_app.ft_vw_sign_symbol_DELETE();
