; foon2pddl, encoding state, level 3: 17 of 101 units after relevance pruning
; goal: tomato soup (1 candidate node)
; kitchen: example_kitchen.txt (51 nodes)
(define (domain foon-state-50517ce2)
  (:requirements :strips)
  (:constants
    basil
    bottle
    bowl
    carton
    cutting_board
    immersion_blender
    knife
    ladle
    olive_oil
    onion
    pot
    stove
    tomato
    tomato_soup
    vegetable_broth
    wooden_spoon
  )
  (:predicates
    (available ?o)  ; the object is in the kitchen or was made
    (is-chopped ?o)  ; ?o is chopped
    (is-chunky ?o)  ; ?o is chunky
    (is-empty ?o)  ; ?o is empty
    (is-fresh ?o)  ; ?o is fresh
    (is-off ?o)  ; ?o is off
    (is-on ?o)  ; ?o is on
    (is-peeled ?o)  ; ?o is peeled
    (is-pureed ?o)  ; ?o is pureed
    (is-sauteed ?o)  ; ?o is sauteed
    (is-whole ?o)  ; ?o is whole
    (contains ?o ?r)  ; ?o contains [?r] or {?r}
    (garnished ?o ?r)  ; ?o garnished [?r] or {?r}
    (in ?o ?r)  ; ?o in [?r] or {?r}
    (on ?o ?r)  ; ?o on [?r] or {?r}
  )

  (:action turn_on_u23
    ; unit 23: turn on from 03-scrambled_eggs.foon:80, 04-pancakes.foon:85, 05-french_toast.foon:92, ... (1 more)
    ; turn on: stove (off) -> stove (on)
    :parameters ()
    :precondition (and
      (available stove)
      (is-off stove)
    )
    :effect (and
      (is-on stove)
      (not (is-off stove))
    )
  )

  (:action pick-and-place_u47
    ; unit 47: pick-and-place from 06-tomato_soup.foon:3, 07-guacamole.foon:105, 08-greek_salad.foon:53
    ; pick-and-place: cutting board (empty), onion (whole) -> cutting board (contains {onion}), onion (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available onion)
      (is-empty cutting_board)
      (is-whole onion)
    )
    :effect (and
      (contains cutting_board onion)
      (on onion cutting_board)
      (not (is-empty cutting_board))
    )
  )

  (:action peel_u48
    ; unit 48: peel from 06-tomato_soup.foon:14, 07-guacamole.foon:116, 08-greek_salad.foon:64
    ; peel: cutting board (contains {onion}), onion (on [cutting board], whole), knife -> cutting board (contains {onion}), onion (on [cutting board], peeled), knife
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available knife)
      (available onion)
      (contains cutting_board onion)
      (is-whole onion)
      (on onion cutting_board)
    )
    :effect (and
      (is-peeled onion)
      (not (is-whole onion))
    )
  )

  (:action chop_u49
    ; unit 49: chop from 06-tomato_soup.foon:28, 07-guacamole.foon:130
    ; chop: cutting board (contains {onion}), onion (on [cutting board], peeled), knife -> cutting board (contains {onion}), onion (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available knife)
      (available onion)
      (contains cutting_board onion)
      (is-peeled onion)
      (on onion cutting_board)
    )
    :effect (and
      (is-chopped onion)
      (not (is-peeled onion))
    )
  )

  (:action pick-and-place_u50
    ; unit 50: pick-and-place from 06-tomato_soup.foon:42, 07-guacamole.foon:156, 08-greek_salad.foon:28
    ; pick-and-place: cutting board (empty), tomato (whole) -> cutting board (contains {tomato}), tomato (on [cutting board], whole)
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available tomato)
      (is-empty cutting_board)
      (is-whole tomato)
    )
    :effect (and
      (contains cutting_board tomato)
      (on tomato cutting_board)
      (not (is-empty cutting_board))
    )
  )

  (:action chop_u51
    ; unit 51: chop from 06-tomato_soup.foon:53, 07-guacamole.foon:167, 08-greek_salad.foon:39
    ; chop: cutting board (contains {tomato}), tomato (on [cutting board], whole), knife -> cutting board (contains {tomato}), tomato (chopped, on [cutting board]), knife
    :parameters ()
    :precondition (and
      (available cutting_board)
      (available knife)
      (available tomato)
      (contains cutting_board tomato)
      (is-whole tomato)
      (on tomato cutting_board)
    )
    :effect (and
      (is-chopped tomato)
      (not (is-whole tomato))
    )
  )

  (:action pick-and-place_u52
    ; unit 52: pick-and-place from 06-tomato_soup.foon:67
    ; pick-and-place: pot (empty), stove (off) -> pot (empty, on [stove])
    :parameters ()
    :precondition (and
      (available pot)
      (available stove)
      (is-empty pot)
      (is-off stove)
    )
    :effect (and
      (on pot stove)
    )
  )

  (:action pour_u53
    ; unit 53: pour from 06-tomato_soup.foon:82
    ; pour: pot (empty, on [stove]), olive oil (in [bottle]) -> pot (contains {olive oil}, on [stove]), olive oil (in [pot])
    :parameters ()
    :precondition (and
      (available olive_oil)
      (available pot)
      (in olive_oil bottle)
      (is-empty pot)
      (on pot stove)
    )
    :effect (and
      (contains pot olive_oil)
      (in olive_oil pot)
      (not (in olive_oil bottle))
      (not (is-empty pot))
    )
  )

  (:action pick-and-place_u54
    ; unit 54: pick-and-place from 06-tomato_soup.foon:94
    ; pick-and-place: pot (contains {olive oil}, on [stove]), onion (chopped, on [cutting board]) -> pot (contains {olive oil, onion}, on [stove]), onion (chopped, in [pot])
    :parameters ()
    :precondition (and
      (available onion)
      (available pot)
      (contains pot olive_oil)
      (is-chopped onion)
      (on onion cutting_board)
      (on pot stove)
    )
    :effect (and
      (contains pot onion)
      (in onion pot)
      (not (on onion cutting_board))
    )
  )

  (:action saute_u55
    ; unit 55: saute from 06-tomato_soup.foon:108
    ; saute: stove (on), olive oil (in [pot]), onion (chopped, in [pot]), wooden spoon -> onion (in [pot], sauteed), wooden spoon
    :parameters ()
    :precondition (and
      (available olive_oil)
      (available onion)
      (available stove)
      (available wooden_spoon)
      (in olive_oil pot)
      (in onion pot)
      (is-chopped onion)
      (is-on stove)
    )
    :effect (and
      (is-sauteed onion)
      (not (is-chopped onion))
    )
  )

  (:action pick-and-place_u56
    ; unit 56: pick-and-place from 06-tomato_soup.foon:122
    ; pick-and-place: pot (contains {olive oil, onion}, on [stove]), onion (in [pot], sauteed), tomato (chopped, on [cutting board]) -> pot (contains {olive oil, onion, tomato}, on [stove]), tomato (chopped, in [pot])
    :parameters ()
    :precondition (and
      (available onion)
      (available pot)
      (available tomato)
      (contains pot olive_oil)
      (contains pot onion)
      (in onion pot)
      (is-chopped tomato)
      (is-sauteed onion)
      (on pot stove)
      (on tomato cutting_board)
    )
    :effect (and
      (contains pot tomato)
      (in tomato pot)
      (not (on tomato cutting_board))
    )
  )

  (:action pour_u57
    ; unit 57: pour from 06-tomato_soup.foon:139
    ; pour: pot (contains {olive oil, onion, tomato}, on [stove]), vegetable broth (in [carton]) -> pot (contains {olive oil, onion, tomato, vegetable broth}, on [stove]), vegetable broth (in [pot])
    :parameters ()
    :precondition (and
      (available pot)
      (available vegetable_broth)
      (contains pot olive_oil)
      (contains pot onion)
      (contains pot tomato)
      (in vegetable_broth carton)
      (on pot stove)
    )
    :effect (and
      (contains pot vegetable_broth)
      (in vegetable_broth pot)
      (not (in vegetable_broth carton))
    )
  )

  (:action simmer_u58
    ; unit 58: simmer from 06-tomato_soup.foon:151
    ; simmer: stove (on), pot (contains {olive oil, onion, tomato, vegetable broth}, on [stove]), olive oil (in [pot]), onion (in [pot], sauteed), tomato (chopped, in [pot]), vegetable broth (in [pot]) -> pot (contains {tomato soup}, on [stove...
    :parameters ()
    :precondition (and
      (available olive_oil)
      (available onion)
      (available pot)
      (available stove)
      (available tomato)
      (available vegetable_broth)
      (contains pot olive_oil)
      (contains pot onion)
      (contains pot tomato)
      (contains pot vegetable_broth)
      (in olive_oil pot)
      (in onion pot)
      (in tomato pot)
      (in vegetable_broth pot)
      (is-chopped tomato)
      (is-on stove)
      (is-sauteed onion)
      (on pot stove)
    )
    :effect (and
      (available tomato_soup)
      (contains pot tomato_soup)
      (in tomato_soup pot)
      (is-chunky tomato_soup)
      (not (contains pot olive_oil))
      (not (contains pot onion))
      (not (contains pot tomato))
      (not (contains pot vegetable_broth))
    )
  )

  (:action turn_on_u59
    ; unit 59: turn on from 06-tomato_soup.foon:174
    ; turn on: immersion blender (off) -> immersion blender (on)
    :parameters ()
    :precondition (and
      (available immersion_blender)
      (is-off immersion_blender)
    )
    :effect (and
      (is-on immersion_blender)
      (not (is-off immersion_blender))
    )
  )

  (:action blend_u60
    ; unit 60: blend from 06-tomato_soup.foon:180
    ; blend: immersion blender (on), pot (contains {tomato soup}, on [stove]), tomato soup (chunky, in [pot]) -> tomato soup (in [pot], pureed), immersion blender (on)
    :parameters ()
    :precondition (and
      (available immersion_blender)
      (available pot)
      (available tomato_soup)
      (contains pot tomato_soup)
      (in tomato_soup pot)
      (is-chunky tomato_soup)
      (is-on immersion_blender)
      (on pot stove)
    )
    :effect (and
      (is-pureed tomato_soup)
      (not (is-chunky tomato_soup))
    )
  )

  (:action scoop_u61
    ; unit 61: scoop from 06-tomato_soup.foon:195
    ; scoop: pot (contains {tomato soup}, on [stove]), tomato soup (in [pot], pureed), ladle, bowl (empty) -> bowl (contains {tomato soup}), tomato soup (in [bowl], pureed), ladle
    :parameters ()
    :precondition (and
      (available bowl)
      (available ladle)
      (available pot)
      (available tomato_soup)
      (contains pot tomato_soup)
      (in tomato_soup pot)
      (is-empty bowl)
      (is-pureed tomato_soup)
      (on pot stove)
    )
    :effect (and
      (contains bowl tomato_soup)
      (in tomato_soup bowl)
      (not (in tomato_soup pot))
      (not (is-empty bowl))
    )
  )

  (:action sprinkle_u62
    ; unit 62: sprinkle from 06-tomato_soup.foon:212
    ; sprinkle: bowl (contains {tomato soup}), tomato soup (in [bowl], pureed), basil (fresh) -> bowl (contains {basil, tomato soup}), tomato soup (garnished {basil}, in [bowl], pureed), basil (on [tomato soup])
    :parameters ()
    :precondition (and
      (available basil)
      (available bowl)
      (available tomato_soup)
      (contains bowl tomato_soup)
      (in tomato_soup bowl)
      (is-fresh basil)
      (is-pureed tomato_soup)
    )
    :effect (and
      (contains bowl basil)
      (garnished tomato_soup basil)
      (on basil tomato_soup)
      (not (is-fresh basil))
    )
  )
)
