!> The catalog of the mesh commands: LIRE_MAILLAGE, PRE_GIBI, DEFI_GROUP, MODI_MAILLAGE,
!> CREA_MAILLAGE.
!> Part of THE command catalog (deck_catalog_data gathers the parts): keywords, types,
!> cardinality, defaults, allowed values, rules and conditional blocks as Code_Aster's own
!> catalog describes them (code_aster/Cata/Commands/lire_maillage.py, defi_group.py,
!> modi_maillage.py, crea_maillage.py; U4.21.01, U4.22.01, U4.23.04, U4.23.02), for the
!> options parasol builds. Options of Code_Aster that need what parasol does not have
!> (X-FEM cracks, prestressing cables, volume cells) are left out, so a deck naming
!> one is told at its keyword.
!>
!> DEFI_GROUP and MODI_MAILLAGE modify their mesh in place (Code_Aster's reentrant='o:...':
!> the result is the MAILLAGE concept, reuse= naming it).
module catalog_mesh
    use kinds, only: dp
    use deck_catalog, only: catalog_t, MANY, RULE_UN_PARMI, RULE_AU_MOINS_UN, RULE_EXCLUS, &
        RULE_PRESENT_ABSENT
    use number_limits, only: MAX_LENGTH
    use catalog_common, only: OUI_NON, ANGLE_MAX
    implicit none
    private
    public :: describe_mesh_commands

    !> TYPE_MAILLE of CREA_GROUP_MA (Code_Aster's list: dimensions and cell types).
    character(len=*), parameter :: CELL_TYPE_INTO = 'TOUT 1D 2D 3D POI1 SEG2 SEG3 SEG4 ' // &
        'TRIA3 TRIA6 TRIA7 QUAD4 QUAD8 QUAD9 TETRA4 TETRA10 PENTA6 PENTA15 PENTA18 HEXA8 ' // &
        'HEXA20 HEXA27 PYRAM5 PYRAM13'
    !> CRIT_NOEUD of the geometric cell selections (SPHERE, CYLINDRE, BANDE).
    character(len=*), parameter :: CELL_NODE_CRITERIA = 'TOUS AU_MOINS_UN MAJORITE'

contains

    subroutine describe_mesh_commands(c)
        type(catalog_t), intent(inout) :: c
        call describe_lire_maillage(c)
        call describe_pre_gibi(c)
        call describe_defi_group(c)
        call describe_modi_maillage(c)
        call describe_crea_maillage(c)
    end subroutine describe_mesh_commands

    ! LIRE_MAILLAGE (lire_maillage.py). PARTITIONNEUR, INFO_MED, CREA_GROUP_COUL and VERI_MAIL
    ! are accepted with no effect: parasol runs one process on the whole mesh, and checks
    ! every mesh it reads for degenerate cells whatever VERI_MAIL says.
    subroutine describe_lire_maillage(c)
        type(catalog_t), intent(inout) :: c
        call c%command('LIRE_MAILLAGE', 'maillage')
        call c%key('FORMAT', 'TXM', def='MED', into='ASTER GIBI GMSH IDEAS MED')
        call c%fact('VERI_MAIL', noop=.true.)
        call c%key('VERIF', 'TXM', def='OUI', into=OUI_NON, noop=.true.)
        call c%key('APLAT', 'R', def='1.0E-3', noop=.true.)
        call c%end_fact()
        call c%bloc(key='FORMAT', equals='ASTER GIBI GMSH IDEAS')
        call c%key('UNITE', 'I', def='20', vmin=2.0_dp)
        call c%end_bloc()
        call c%bloc(key='FORMAT', equals='MED')
        call c%key('UNITE', 'I', def='20', vmin=2.0_dp)
        call c%key('NOM_MED', 'TXM')
        call c%key('INFO_MED', 'I', def='0', into='0 1', noop=.true.)
        call c%key('PARTITIONNEUR', 'TXM', def='SANS', into='SANS PTSCOTCH', noop=.true.)
        call c%end_bloc()
        call c%bloc(key='FORMAT', equals='IDEAS')
        call c%key('CREA_GROUP_COUL', 'TXM', def='NON', into=OUI_NON)
        call c%end_bloc()
        call c%key('INFO', 'I', def='1', into='0 1 2')
    end subroutine describe_lire_maillage

    ! PRE_GIBI (pre_gibi.py): the GIBI file on UNITE_GIBI converted to a .mail on
    ! UNITE_MAILLAGE, which a later LIRE_MAILLAGE(FORMAT='ASTER') reads.
    subroutine describe_pre_gibi(c)
        type(catalog_t), intent(inout) :: c
        call c%command('PRE_GIBI', '')
        call c%key('UNITE_GIBI', 'I', def='19', vmin=2.0_dp)
        call c%key('UNITE_MAILLAGE', 'I', def='20', vmin=2.0_dp)
    end subroutine describe_pre_gibi

    ! DEFI_GROUP (defi_group.py): DETR_GROUP_* first, then CREA_GROUP_MA, then CREA_GROUP_NO,
    ! each occurrence seeing the groups of the earlier ones (op0104).
    subroutine describe_defi_group(c)
        type(catalog_t), intent(inout) :: c
        call c%command('DEFI_GROUP', 'maillage', reentrant='o:MAILLAGE')
        call c%key('MAILLAGE', 'maillage', req=.true.)
        call c%rule(RULE_AU_MOINS_UN, 'CREA_GROUP_MA CREA_GROUP_NO DETR_GROUP_NO DETR_GROUP_MA')
        call c%fact('DETR_GROUP_MA', max=MANY)
        call c%key('NOM', 'TXM', max=MANY, req=.true.)
        call c%end_fact()
        call c%fact('DETR_GROUP_NO', max=MANY)
        call c%key('NOM', 'TXM', max=MANY, req=.true.)
        call c%end_fact()
        call describe_crea_group_ma(c)
        call describe_crea_group_no(c)
        call c%key('ALARME', 'TXM', def='OUI', into=OUI_NON)
        call c%key('INFO', 'I', into='1 2')
    end subroutine describe_defi_group

    subroutine describe_crea_group_ma(c)
        type(catalog_t), intent(inout) :: c
        call c%fact('CREA_GROUP_MA', max=MANY)
        call c%rule(RULE_UN_PARMI, 'TOUT GROUP_MA MAILLE INTERSEC UNION DIFFE OPTION')
        call c%key('NOM', 'TXM', req=.true.)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM')
        call c%key('MAILLE', 'TXM', max=MANY)
        call c%key('INTERSEC', 'TXM', max=MANY)
        call c%key('UNION', 'TXM', max=MANY)
        call c%key('DIFFE', 'TXM', max=MANY)
        call c%key('TYPE_MAILLE', 'TXM', def='TOUT', into=CELL_TYPE_INTO)
        call c%key('OPTION', 'TXM', into='FACE_NORMALE SPHERE CYLINDRE BANDE APPUI')
        call c%bloc(exists='GROUP_MA')
        call c%rule(RULE_EXCLUS, 'POSITION NUME_INIT')
        call c%key('NUME_INIT', 'I', vmin=1.0_dp)
        call c%key('POSITION', 'TXM', into='INIT FIN MILIEU')
        call c%bloc(exists='NUME_INIT')
        call c%key('NUME_FIN', 'I', vmin=1.0_dp)
        call c%end_bloc()
        call c%end_bloc()
        call c%bloc(key='OPTION', equals='FACE_NORMALE')
        call c%rule(RULE_UN_PARMI, 'ANGL_NAUT VECT_NORMALE')
        call direction_keys(c, 2)
        call c%key('ANGL_PREC', 'R', def='0.5', vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%key('VERI_SIGNE', 'TXM', def='OUI', into=OUI_NON)
        call c%end_bloc()
        call c%bloc(key='OPTION', equals='SPHERE')
        call centre_keys(c)
        call c%key('RAYON', 'R', req=.true., vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%key('CRIT_NOEUD', 'TXM', def='AU_MOINS_UN', into=CELL_NODE_CRITERIA)
        call c%end_bloc()
        call c%bloc(key='OPTION', equals='CYLINDRE')
        call centre_keys(c)
        call c%rule(RULE_UN_PARMI, 'ANGL_NAUT VECT_NORMALE')
        call c%key('RAYON', 'R', req=.true., vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call direction_keys(c, 2)
        call c%key('CRIT_NOEUD', 'TXM', def='AU_MOINS_UN', into=CELL_NODE_CRITERIA)
        call c%end_bloc()
        call c%bloc(key='OPTION', equals='BANDE')
        call centre_keys(c)
        call c%rule(RULE_UN_PARMI, 'ANGL_NAUT VECT_NORMALE')
        call c%key('DIST', 'R', req=.true., vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call direction_keys(c, 2)
        call c%key('CRIT_NOEUD', 'TXM', def='AU_MOINS_UN', into=CELL_NODE_CRITERIA)
        call c%end_bloc()
        call c%bloc(key='OPTION', equals='APPUI')
        call c%rule(RULE_UN_PARMI, 'NOEUD GROUP_NO')
        call c%key('NOEUD', 'TXM', max=MANY)
        call c%key('GROUP_NO', 'TXM', max=MANY)
        call c%key('TYPE_APPUI', 'TXM', req=.true., into='AU_MOINS_UN TOUT SOMMET MAJORITE')
        call c%end_bloc()
        call c%end_fact()
    end subroutine describe_crea_group_ma

    subroutine describe_crea_group_no(c)
        type(catalog_t), intent(inout) :: c
        call c%fact('CREA_GROUP_NO', max=MANY)
        call c%key('OPTION', 'TXM', into='ENV_SPHERE ENV_CYLINDRE PLAN SEGM_DROI_ORDO ' // &
                   'NOEUD_ORDO INCLUSION')
        call c%bloc(absent='OPTION')
        call c%rule(RULE_UN_PARMI, 'TOUT_GROUP_MA GROUP_MA GROUP_NO NOEUD INTERSEC UNION DIFFE')
        call c%key('TOUT_GROUP_MA', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%key('GROUP_NO', 'TXM', max=MANY)
        call c%key('NOEUD', 'TXM', max=MANY)
        call c%key('INTERSEC', 'TXM', max=MANY)
        call c%key('UNION', 'TXM', max=MANY)
        call c%key('DIFFE', 'TXM', max=MANY)
        call c%bloc(exists='GROUP_MA')
        call c%key('NOM', 'TXM', max=MANY)
        call c%key('CRIT_NOEUD', 'TXM', def='TOUS', into='TOUS SOMMET MILIEU CENTRE')
        call c%end_bloc()
        call c%bloc(exists='GROUP_NO')
        call c%rule(RULE_EXCLUS, 'POSITION NUME_INIT')
        call c%key('NUME_INIT', 'I', vmin=1.0_dp)
        call c%key('POSITION', 'TXM', into='INIT FIN MILIEU')
        call c%bloc(exists='NUME_INIT')
        call c%key('NUME_FIN', 'I', vmin=1.0_dp)
        call c%end_bloc()
        call c%end_bloc()
        call c%bloc(absent='GROUP_MA TOUT_GROUP_MA')
        call c%key('NOM', 'TXM', req=.true.)
        call c%end_bloc()
        call c%end_bloc()
        call c%bloc(key='OPTION', equals='ENV_SPHERE')
        call c%key('NOM', 'TXM', req=.true.)
        call centre_keys(c)
        call c%key('RAYON', 'R', req=.true., vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%key('PRECISION', 'R', req=.true., vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%end_bloc()
        call c%bloc(key='OPTION', equals='ENV_CYLINDRE')
        call c%key('NOM', 'TXM', req=.true.)
        call centre_keys(c)
        call c%rule(RULE_UN_PARMI, 'ANGL_NAUT VECT_NORMALE')
        call c%key('RAYON', 'R', req=.true., vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call direction_keys(c, 3)
        call c%key('PRECISION', 'R', req=.true., vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%end_bloc()
        call c%bloc(key='OPTION', equals='PLAN')
        call c%key('NOM', 'TXM', req=.true.)
        call centre_keys(c)
        call c%rule(RULE_UN_PARMI, 'ANGL_NAUT VECT_NORMALE')
        call direction_keys(c, 3)
        call c%key('PRECISION', 'R', req=.true., vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%end_bloc()
        call c%bloc(key='OPTION', equals='SEGM_DROI_ORDO')
        call c%key('NOM', 'TXM', req=.true.)
        call c%key('GROUP_NO', 'TXM', max=MANY)
        call c%key('GROUP_NO_ORIG', 'TXM', req=.true.)
        call c%key('GROUP_NO_EXTR', 'TXM', req=.true.)
        call c%key('PRECISION', 'R', req=.true., vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%key('CRITERE', 'TXM', req=.true., into='ABSOLU RELATIF')
        call c%end_bloc()
        call c%bloc(key='OPTION', equals='NOEUD_ORDO')
        call c%key('NOM', 'TXM', req=.true.)
        call c%key('GROUP_MA', 'TXM', max=MANY, req=.true.)
        call c%key('GROUP_NO_ORIG', 'TXM')
        call c%key('GROUP_NO_EXTR', 'TXM')
        call c%key('VECT_ORIE', 'R', max=3, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%key('ORIGINE', 'TXM', into='SANS')
        call c%end_bloc()
        call c%bloc(key='OPTION', equals='INCLUSION')
        call c%key('NOM', 'TXM', req=.true.)
        call c%key('CAS_FIGURE', 'TXM', req=.true., into='2D 3D 2.5D')
        call c%key('DISTANCE_MAX', 'R', vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%key('GROUP_MA', 'TXM', max=MANY, req=.true.)
        call c%key('GROUP_MA_INCL', 'TXM', max=MANY, req=.true.)
        call c%key('MAILLAGE_INCL', 'maillage')
        call c%end_bloc()
        call c%end_fact()
    end subroutine describe_crea_group_no

    ! POINT | NOEUD_CENTRE | GROUP_NO_CENTRE, exactly one (the centre of a geometric option).
    subroutine centre_keys(c)
        type(catalog_t), intent(inout) :: c
        call c%rule(RULE_UN_PARMI, 'POINT NOEUD_CENTRE GROUP_NO_CENTRE')
        call c%key('POINT', 'R', max=3, vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%key('NOEUD_CENTRE', 'TXM')
        call c%key('GROUP_NO_CENTRE', 'TXM')
    end subroutine centre_keys

    ! ANGL_NAUT (at most `angles` values, degrees) and VECT_NORMALE (at most 3).
    subroutine direction_keys(c, angles)
        type(catalog_t), intent(inout) :: c
        integer, intent(in) :: angles
        call c%key('ANGL_NAUT', 'R', max=angles, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%key('VECT_NORMALE', 'R', max=3, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
    end subroutine direction_keys

    ! MODI_MAILLAGE (modi_maillage.py): the geometric transformations in Code_Aster's order
    ! (TRANSLATION, MODI_BASE, ROTATION, SYMETRIE, ECHELLE; op0154), then the orientations.
    subroutine describe_modi_maillage(c)
        type(catalog_t), intent(inout) :: c
        call c%command('MODI_MAILLAGE', 'maillage', reentrant='o:MAILLAGE')
        call c%key('MAILLAGE', 'maillage', req=.true.)
        call c%rule(RULE_AU_MOINS_UN, 'DEFORME ORIE_PEAU ORIE_NORM_COQUE TRANSLATION ' // &
                    'ROTATION MODI_BASE ECHELLE SYMETRIE ORIE_LIGNE')
        call c%rule(RULE_PRESENT_ABSENT, 'DEFORME ORIE_PEAU ORIE_NORM_COQUE ORIE_LIGNE')
        call c%rule(RULE_PRESENT_ABSENT, 'ORIE_PEAU DEFORME ORIE_NORM_COQUE ORIE_LIGNE')
        call c%rule(RULE_PRESENT_ABSENT, 'ORIE_NORM_COQUE DEFORME ORIE_PEAU ORIE_LIGNE')
        call c%rule(RULE_EXCLUS, 'ROTATION MODI_BASE')
        call c%rule(RULE_EXCLUS, 'SYMETRIE ROTATION')
        call c%rule(RULE_EXCLUS, 'SYMETRIE TRANSLATION')
        call c%rule(RULE_EXCLUS, 'SYMETRIE MODI_BASE')
        call c%rule(RULE_EXCLUS, 'SYMETRIE ECHELLE')
        call c%fact('DEFORME')
        call c%key('OPTION', 'TXM', req=.true., into='TRAN')
        call c%rule(RULE_UN_PARMI, 'DEPL ALEA')
        call c%key('DEPL', 'cham_no_sdaster')
        call c%key('ALEA', 'R', vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%end_fact()
        call c%fact('ORIE_PEAU', max=MANY)
        call c%key('GROUP_MA_PEAU', 'TXM', max=MANY, req=.true.)
        call c%key('GROUP_MA_INTERNE', 'TXM', max=MANY)
        call c%end_fact()
        call c%fact('ORIE_NORM_COQUE', max=MANY)
        call c%key('GROUP_MA', 'TXM', max=MANY, req=.true.)
        call c%key('VECT_NORM', 'R', max=3, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%bloc(exists='VECT_NORM')
        call c%key('GROUP_NO', 'TXM')
        call c%end_bloc()
        call c%end_fact()
        call c%fact('ORIE_LIGNE', max=MANY)
        call c%key('GROUP_MA', 'TXM', max=MANY, req=.true.)
        call c%key('VECT_TANG', 'R', max=3, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%bloc(exists='VECT_TANG')
        call c%key('GROUP_NO', 'TXM', req=.true.)
        call c%end_bloc()
        call c%end_fact()
        call c%fact('MODI_BASE')
        call c%key('VECT_X', 'R', min=2, max=3, req=.true., vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%key('VECT_Y', 'R', min=2, max=3, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%end_fact()
        call c%key('ECHELLE', 'R', vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%key('TRANSLATION', 'R', min=2, max=3, vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%fact('ROTATION', max=MANY)
        call c%rule(RULE_EXCLUS, 'DIR POIN_2')
        call c%key('POIN_1', 'R', min=2, max=3, req=.true., vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%key('ANGLE', 'R', def='0.0', vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%key('POIN_2', 'R', min=2, max=3, vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%key('DIR', 'R', min=2, max=3, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%end_fact()
        call c%fact('SYMETRIE')
        call c%key('POINT', 'R', min=2, max=3, req=.true., vmin=-MAX_LENGTH, vmax=MAX_LENGTH)
        call c%key('AXE_1', 'R', min=2, max=3, req=.true., vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%key('AXE_2', 'R', min=3, max=3, vmin=-ANGLE_MAX, vmax=ANGLE_MAX)
        call c%end_fact()
        call c%key('INFO', 'I', def='1', into='1 2')
    end subroutine describe_modi_maillage

    ! CREA_MAILLAGE (crea_maillage.py): a new mesh from MAILLAGE (not reentrant).
    subroutine describe_crea_maillage(c)
        type(catalog_t), intent(inout) :: c
        call c%command('CREA_MAILLAGE', 'maillage')
        call c%key('MAILLAGE', 'maillage', req=.true.)
        call c%rule(RULE_UN_PARMI, 'CREA_MAILLE CREA_POI1 LINE_QUAD MODI_MAILLE QUAD_LINE ' // &
                    'RESTREINT')
        call c%fact('CREA_POI1', max=MANY)
        call c%rule(RULE_AU_MOINS_UN, 'TOUT GROUP_MA GROUP_NO NOEUD')
        call c%key('NOM_GROUP_MA', 'TXM', max=MANY)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%key('GROUP_NO', 'TXM', max=MANY)
        call c%key('NOEUD', 'TXM', max=MANY)
        call c%end_fact()
        call c%fact('CREA_MAILLE', max=MANY)
        call c%rule(RULE_UN_PARMI, 'TOUT GROUP_MA')
        call c%key('NOM', 'TXM', req=.true.)
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%end_fact()
        call c%fact('MODI_MAILLE', max=MANY)
        call c%rule(RULE_AU_MOINS_UN, 'TOUT MAILLE GROUP_MA')
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('MAILLE', 'TXM', max=MANY)
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%key('OPTION', 'TXM', req=.true., into='TRIA6_7 QUAD8_9 SEG3_4 QUAD_TRIA3')
        call c%end_fact()
        ! LINE_QUAD and QUAD_LINE: Code_Aster's UN_PARMI("TOUT", "GROUP_MA", TOUT="OUI")
        ! makes TOUT='OUI' the default when neither is given: so does the handler.
        call c%fact('LINE_QUAD')
        call c%rule(RULE_EXCLUS, 'TOUT GROUP_MA')
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%end_fact()
        call c%fact('QUAD_LINE')
        call c%rule(RULE_EXCLUS, 'TOUT GROUP_MA')
        call c%key('TOUT', 'TXM', into='OUI')
        call c%key('GROUP_MA', 'TXM', max=MANY)
        call c%end_fact()
        call c%fact('RESTREINT')
        call c%key('GROUP_MA', 'TXM', max=MANY, req=.true.)
        call c%key('TOUT_GROUP_MA', 'TXM', def='NON', into=OUI_NON)
        call c%key('GROUP_NO', 'TXM', max=MANY)
        call c%key('TOUT_GROUP_NO', 'TXM', def='NON', into=OUI_NON)
        call c%end_fact()
        call c%key('TITRE', 'TXM')
        call c%key('INFO', 'I', def='1', into='1 2')
    end subroutine describe_crea_maillage

end module catalog_mesh
