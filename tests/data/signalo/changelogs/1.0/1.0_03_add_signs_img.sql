UPDATE signalo_db.vl_official_sign

    SET img_de='502-l.svg', img_fr='502-l.svg', img_it='502-l.svg', img_ro='502-l.svg',
	directional_sign=true,
	img_de_right='502-r.svg', img_fr_right='502-r.svg', img_it_right='502-r.svg', img_ro_right='502-r.svg'

    WHERE id = '5.02';
